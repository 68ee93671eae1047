#pragma once
#include "core/scene/binding_table.hpp"

namespace pbr {

// The post module's binding points, one table for C++ and GLSL: the post pass's settings block, the exposure
// meter's state (the histogram, the adaptation and the post pass read it) and FXAA's edge list.
constexpr BindingPoint kPostUbo{"POST_UBO", BindingKind::UniformBuffer, 3};
constexpr BindingPoint kExposureSsbo{"EXPOSURE_SSBO", BindingKind::StorageBuffer, 19};
// FXAA's list of the pixels on an edge (post/fxaa_pass.hpp).
constexpr BindingPoint kFxaaEdgesSsbo{"FXAA_EDGES_SSBO", BindingKind::StorageBuffer, 22};

}  // namespace pbr
