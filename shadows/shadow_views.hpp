#pragma once
#include <array>

#include <glm/vec3.hpp>

#include "core/scene/camera.hpp"
#include "shadows/shadow_plan.hpp"

namespace pbr {

// Two unit vectors completing unit `axis` to an orthonormal frame, the same for the same axis every frame:
// right = normalize(cross(axis, helper)), up = cross(right, axis), the helper y unless the axis is within 8 degrees
// of it, then x.
void frameAround(const glm::vec3& axis, glm::vec3& right, glm::vec3& up);
bool frameAroundX(const glm::vec3& axis);  // whether frameAround's helper is x

// The view depths (distance along the camera's axis) the cascades of a directional light cover: from where the
// receivers begin in view, or the near plane, to where they end, or the far plane, and at least a thousandth of
// the depth they begin at.
struct CascadeSplits {
  int count = 0;  // 0 when the scene lies outside the camera's depth range
  float begin = 0.0f;
  std::array<float, kCascades> ends{};
};
// Ends by the practical split scheme (Zhang et al. 2006, "Parallel-Split Shadow Maps"), lambda 0.75: three parts
// logarithmic to one uniform.
CascadeSplits cascadeSplits(const Camera& camera, float nearDepth, float farDepth, int count);

// Cascade `cascade` of a light travelling along unit `direction`: an orthographic square around the bounding
// sphere of the camera frustum's slice (its size does not change as the camera turns), its centre snapped to whole
// texels in light space (the texel grid does not crawl as the camera moves), deep enough to hold every caster of
// the scene's bounds.
ShadowViewPlan cascadeView(const Camera& camera, float aspect, const CascadeSplits& splits, int cascade,
                           const glm::vec3& direction, const WorldBounds& scene, int size);

// A perspective view from `apex` along unit `axis` whose square of `size` texels covers the half-angle tangent
// `tanHalf` (1 for a cube face) inside a border of `border` texels, reversed Z with an infinite far plane and a
// near plane at a thousandth of the light's radius `radius`.
ShadowViewPlan perspectiveView(const glm::vec3& apex, const glm::vec3& axis, float tanHalf, float radius, int size,
                               int border);

}  // namespace pbr
