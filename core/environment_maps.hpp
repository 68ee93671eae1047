#pragma once
#include "core/binding_table.hpp"
#include "core/gl.hpp"

namespace pbr {

// Image-based lighting as shaders sample it (shaders/ibl/ibl_sample.glsl): the spherical-harmonic irradiance
// block, the GGX-prefiltered specular cube map and the split-sum DFG table, each texture with its sampler. The
// contract between the pass that makes the maps (ibl/) and the passes that read them (lighting/), neither of
// which knows the other. Handles only: the maps belong to their maker.
struct EnvironmentMaps {
  GLuint irradianceBlock = 0;  // uniform buffer holding one IblBlock
  GLuint specularCube = 0, specularSampler = 0;
  GLuint dfgTable = 0, dfgSampler = 0;
};

// Where ibl_sample.glsl reads the maps; clear of the frame block, the G-buffer and material units (0-4) and the
// lighting pass's own points, since the lighting pass binds them together.
constexpr BindingPoint kIblUbo{"IBL_UBO", BindingKind::UniformBuffer, 5};
constexpr BindingPoint kIblSpecularUnit{"IBL_SPECULAR_UNIT", BindingKind::TextureUnit, 8};
constexpr BindingPoint kIblDfgUnit{"IBL_DFG_UNIT", BindingKind::TextureUnit, 9};
// The defines of the three, for programs that sample the maps.
ShaderDefines environmentBindingDefines();

// Binds the maps where ibl_sample.glsl reads them, and turns on seamless cube-map filtering (GL state of the
// whole context).
void bindEnvironmentMaps(const EnvironmentMaps& maps);

}  // namespace pbr
