#include "core/camera.hpp"

#include <glm/gtc/matrix_transform.hpp>

namespace pbr {

glm::mat4 Camera::view() const { return glm::lookAtRH(position, target, up); }

glm::mat4 Camera::projection(float aspect) const {
  return glm::perspectiveRH_ZO(glm::radians(fovYDeg), aspect, farPlane, nearPlane);
}

}  // namespace pbr
