#pragma once
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

namespace pbr {

// std140 mirror of `ObjectBlock` in shaders/gbuffer/object.glsl: one per drawn object.
struct ObjectBlock {
  glm::mat4 model;
  glm::mat4 normalMatrix;  // inverse transpose of the model matrix (upper 3x3 used)
  glm::vec4 baseColor;     // linear rgb
  glm::vec4 material;      // roughness, metalness
};
static_assert(sizeof(ObjectBlock) == 2 * 64 + 2 * 16, "ObjectBlock must match its std140 layout");

}  // namespace pbr
