#pragma once
#include "core/scene/binding_table.hpp"

namespace pbr {

// Where shaders/ibl/ibl_sample.glsl reads the image-based lighting maps (core/gl/environment_maps.hpp); clear of
// the frame block, the G-buffer and material units (0-4) and the lighting pass's own points, since the lighting
// pass binds them together.
constexpr BindingPoint kIblUbo{"IBL_UBO", BindingKind::UniformBuffer, 5};
constexpr BindingPoint kIblSpecularUnit{"IBL_SPECULAR_UNIT", BindingKind::TextureUnit, 8};
constexpr BindingPoint kIblDfgUnit{"IBL_DFG_UNIT", BindingKind::TextureUnit, 9};
// KHR_materials_sheen's prefiltered cube, past the material extensions' map units (17-25) the forward pass binds.
constexpr BindingPoint kIblSheenUnit{"IBL_SHEEN_UNIT", BindingKind::TextureUnit, 26};
// The defines of the four, for programs that sample the maps.
ShaderDefines environmentBindingDefines();

}  // namespace pbr
