#pragma once
// Binding points shared by C++ and GLSL; shaders/common/bindings.glsl mirrors these numbers.
namespace pbr::binding {
constexpr unsigned kFrameUbo = 0;
constexpr unsigned kObjectUbo = 1;
constexpr unsigned kLightingUbo = 2;
constexpr unsigned kPostUbo = 3;
constexpr unsigned kClusterUbo = 4;
constexpr unsigned kLightSsbo = 0;
constexpr unsigned kClusterSsbo = 1;
constexpr unsigned kLightIndexSsbo = 2;
constexpr unsigned kLightVisibleSsbo = 3;
constexpr unsigned kClusterBoundsSsbo = 4;
constexpr unsigned kClusterStatusSsbo = 5;
constexpr unsigned kLightingStatsSsbo = 6;
}  // namespace pbr::binding
