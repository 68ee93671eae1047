#pragma once
#include <glm/vec3.hpp>

namespace pbr {

// A procedural sky for tests and scenes without an environment file: a gradient from the horizon up to the
// zenith and down to the ground (radiance, linear RGB), plus a sun disc of uniform radiance. It lives in core so
// that a Scene can describe its environment without depending on the IBL module that renders it.
struct SkyParams {
  glm::vec3 zenith{0.12f, 0.25f, 0.6f};
  glm::vec3 horizon{0.6f, 0.7f, 0.85f};
  glm::vec3 ground{0.15f, 0.13f, 0.11f};
  glm::vec3 sunDirection{0.4f, 0.5f, -0.77f};  // towards the sun; need not be unit length
  float sunAngularRadiusDeg = 0.27f;           // the real sun's
  glm::vec3 sunRadiance{20000.0f};             // 0 for no sun
};

}  // namespace pbr
