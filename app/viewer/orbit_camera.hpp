#pragma once
#include <glm/vec3.hpp>

#include "core/scene/camera.hpp"

namespace pbr {

// A camera that orbits its target: yaw and pitch about the target, distance to it, and a fly mode that moves
// the target and the eye together. It starts as exactly the given camera, so an untouched view renders the
// same frame as the headless path.
class OrbitCamera {
 public:
  explicit OrbitCamera(const Camera& start);

  const Camera& camera() const { return camera_; }
  float yaw() const { return yaw_; }      // radians about world Y, 0 looking down -Z
  float pitch() const { return pitch_; }  // radians above the target's horizontal plane
  float distance() const { return distance_; }
  // Turns about the target; radians, pitch kept off the poles so that `up` stays usable.
  void orbit(float yawDelta, float pitchDelta);
  // Moves the eye towards the target (factor < 1) or away from it (> 1).
  void zoom(float factor);
  // Moves eye and target together: x right, y up (world), z forward, in units of the distance to the target.
  void fly(const glm::vec3& amount);

 private:
  void place();

  Camera camera_;
  float yaw_ = 0.0f, pitch_ = 0.0f, distance_ = 1.0f;
};

}  // namespace pbr
