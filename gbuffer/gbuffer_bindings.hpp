#pragma once
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
}  // namespace gbuffer_binding

// The frame block's and the geometry pass's points, with which its programs are compiled.
ShaderDefines gbufferBindingDefines();

}  // namespace pbr
