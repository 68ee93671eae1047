#pragma once
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace pbr {

struct Camera {
  glm::vec3 position{0.0f, 2.0f, 6.0f};
  glm::vec3 target{0.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  float fovYDeg = 50.0f;  // perspective
  float nearPlane = 0.1f;
  float farPlane = 100.0f;
  bool orthographic = false;     // parallel rays along the view axis (glTF "orthographic")
  float orthoHalfHeight = 1.0f;  // orthographic: half the view's height in metres (glTF ymag)

  glm::mat4 view() const;
  // Reversed-Z with a [0,1] clip range (glClipControl): depth 1 at the near plane, 0 at the far plane,
  // which spreads float depth precision evenly over distance.
  glm::mat4 projection(float aspect) const;
  // Half the view's width and height at view depth `depth` (distance along the view axis).
  glm::vec2 halfExtent(float depth, float aspect) const;
};

}  // namespace pbr
