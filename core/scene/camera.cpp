#include "core/scene/camera.hpp"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace pbr {

glm::mat4 Camera::view() const { return glm::lookAtRH(position, target, up); }

glm::mat4 Camera::projection(float aspect) const {
  if (orthographic) {
    // Near and far swapped, as for the perspective projection: depth = (z + far) / (far - near), 1 at the near plane.
    const float h = orthoHalfHeight, w = h * aspect;
    return glm::orthoRH_ZO(-w, w, -h, h, farPlane, nearPlane);
  }
  return glm::perspectiveRH_ZO(glm::radians(fovYDeg), aspect, farPlane, nearPlane);
}

glm::vec2 Camera::halfExtent(float depth, float aspect) const {
  if (orthographic) return {orthoHalfHeight * aspect, orthoHalfHeight};
  const float t = std::tan(glm::radians(fovYDeg) * 0.5f);
  return depth * glm::vec2(t * aspect, t);
}

}  // namespace pbr
