#pragma once
#include "core/gl/gl.hpp"
#include "core/scene/environment_bindings.hpp"

namespace pbr {

// Image-based lighting as shaders sample it (shaders/ibl/ibl_sample.glsl): the spherical-harmonic irradiance
// block, the GGX-prefiltered specular cube map and the split-sum DFG table, each texture with its sampler. The
// contract between the pass that makes the maps (ibl/) and the passes that read them (lighting/), neither of
// which knows the other. Handles only: the maps belong to their maker.
struct EnvironmentMaps {
  GLuint irradianceBlock = 0;  // uniform buffer holding one IblBlock
  GLuint specularCube = 0, specularSampler = 0;
  GLuint dfgTable = 0, dfgSampler = 0;
  GLuint sheenCube = 0;  // KHR_materials_sheen's Charlie-prefiltered cube (the specular sampler's filtering); 0: none
};

// Binds the maps where ibl_sample.glsl reads them (core/scene/environment_bindings.hpp), and turns on seamless
// cube-map filtering (GL state of the whole context).
void bindEnvironmentMaps(const EnvironmentMaps& maps);

}  // namespace pbr
