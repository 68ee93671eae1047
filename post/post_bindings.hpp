#pragma once
#include "core/scene/binding_table.hpp"

namespace pbr {

// The post module's binding points, one table for C++ and GLSL: the post pass's settings block, and the exposure
// meter's state (the histogram, the adaptation and the post pass read it).
constexpr BindingPoint kPostUbo{"POST_UBO", BindingKind::UniformBuffer, 3};
constexpr BindingPoint kExposureSsbo{"EXPOSURE_SSBO", BindingKind::StorageBuffer, 19};

}  // namespace pbr
