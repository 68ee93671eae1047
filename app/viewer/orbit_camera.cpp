#include "app/viewer/orbit_camera.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace pbr {

namespace {
constexpr float kMaxPitch = 1.55f;  // just under pi/2: the view never becomes parallel to up
}

OrbitCamera::OrbitCamera(const Camera& start) : camera_(start) {
  const glm::vec3 offset = start.position - start.target;
  distance_ = std::max(glm::length(offset), 1e-3f);
  yaw_ = std::atan2(offset.x, offset.z);
  pitch_ = std::asin(std::clamp(offset.y / distance_, -1.0f, 1.0f));
}

void OrbitCamera::orbit(float yawDelta, float pitchDelta) {
  yaw_ += yawDelta;
  pitch_ = std::clamp(pitch_ + pitchDelta, -kMaxPitch, kMaxPitch);
  place();
}

void OrbitCamera::zoom(float factor) {
  if (camera_.orthographic) {  // a parallel view's size does not change with distance: the view's height does
    camera_.orthoHalfHeight = std::clamp(camera_.orthoHalfHeight * factor, 1e-4f, 1e5f);
    return;
  }
  // Never through the near plane onto the target, never past the far plane.
  distance_ = std::clamp(distance_ * factor, camera_.nearPlane * 2.0f, camera_.farPlane * 0.9f);
  place();
}

void OrbitCamera::fly(const glm::vec3& amount) {
  const glm::vec3 forward = glm::normalize(camera_.target - camera_.position);
  const glm::vec3 right = glm::normalize(glm::cross(forward, camera_.up));
  const glm::vec3 step = (right * amount.x + camera_.up * amount.y + forward * amount.z) * distance_;
  camera_.target += step;
  camera_.position += step;
}

void OrbitCamera::place() {
  const glm::vec3 direction(std::cos(pitch_) * std::sin(yaw_), std::sin(pitch_), std::cos(pitch_) * std::cos(yaw_));
  camera_.position = camera_.target + direction * distance_;
  camera_.up = glm::vec3(0.0f, 1.0f, 0.0f);  // orbiting is about world Y, whatever the scene's camera had
}

}  // namespace pbr
