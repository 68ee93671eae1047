#pragma once
#include <vector>

#include "core/scene/binding_table.hpp"

namespace pbr {

// The geometry pass's binding points, one table for C++ and GLSL (shaders/gbuffer/object.glsl).
namespace gbuffer_binding {
constexpr BindingPoint kObjectUbo{"OBJECT_UBO", BindingKind::UniformBuffer, 1};
// The view-projections of a light's shadow views, drawn together (shaders/gbuffer/shadow_depth.vert).
constexpr BindingPoint kShadowViewsUbo{"SHADOW_VIEWS_UBO", BindingKind::UniformBuffer, 10};
// Units 0-4: the material maps are bound with one glBindTextures call from unit 0.
constexpr BindingPoint kBaseColorMapUnit{"BASE_COLOR_MAP_UNIT", BindingKind::TextureUnit, 0};
constexpr BindingPoint kMetallicRoughnessMapUnit{"METALLIC_ROUGHNESS_MAP_UNIT", BindingKind::TextureUnit, 1};
constexpr BindingPoint kNormalMapUnit{"NORMAL_MAP_UNIT", BindingKind::TextureUnit, 2};
constexpr BindingPoint kOcclusionMapUnit{"OCCLUSION_MAP_UNIT", BindingKind::TextureUnit, 3};
constexpr BindingPoint kEmissiveMapUnit{"EMISSIVE_MAP_UNIT", BindingKind::TextureUnit, 4};
// Units 17-25: the material extensions' maps (extensionMaps, core/scene/scene.hpp, in its order), bound with a
// second glBindTextures call, past the units the lighting module's forward programs use beside them.
constexpr BindingPoint kClearcoatMapUnit{"CLEARCOAT_MAP_UNIT", BindingKind::TextureUnit, 17};
constexpr BindingPoint kClearcoatRoughnessMapUnit{"CLEARCOAT_ROUGHNESS_MAP_UNIT", BindingKind::TextureUnit, 18};
constexpr BindingPoint kClearcoatNormalMapUnit{"CLEARCOAT_NORMAL_MAP_UNIT", BindingKind::TextureUnit, 19};
constexpr BindingPoint kSheenColorMapUnit{"SHEEN_COLOR_MAP_UNIT", BindingKind::TextureUnit, 20};
constexpr BindingPoint kSheenRoughnessMapUnit{"SHEEN_ROUGHNESS_MAP_UNIT", BindingKind::TextureUnit, 21};
constexpr BindingPoint kSpecularMapUnit{"SPECULAR_MAP_UNIT", BindingKind::TextureUnit, 22};
constexpr BindingPoint kSpecularColorMapUnit{"SPECULAR_COLOR_MAP_UNIT", BindingKind::TextureUnit, 23};
constexpr BindingPoint kTransmissionMapUnit{"TRANSMISSION_MAP_UNIT", BindingKind::TextureUnit, 24};
constexpr BindingPoint kThicknessMapUnit{"THICKNESS_MAP_UNIT", BindingKind::TextureUnit, 25};
constexpr auto kFirstExtensionMapUnit = kClearcoatMapUnit.index;
}  // namespace gbuffer_binding

// The points of the material maps, the core's then the extensions', which a draw binds.
std::vector<BindingPoint> materialMapBindings();

// The frame block's and the geometry pass's points, with which its programs are compiled.
ShaderDefines gbufferBindingDefines();

}  // namespace pbr
