#pragma once
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include "core/scene/binding_table.hpp"
#include "core/scene/camera.hpp"

namespace pbr {

// std140 mirror of `FrameBlock` in shaders/common/frame.glsl.
struct FrameBlock {
  glm::mat4 view;
  glm::mat4 projection;
  glm::mat4 viewProjection;
  glm::mat4 inverseView;
  glm::vec4 cameraPosition;  // xyz world, w unused
  glm::vec4 viewport;        // width, height, 1/width, 1/height
  glm::vec4 projParams;      // P[0][0], P[1][1], P[2][2], P[3][2]: view-space position from depth
  glm::vec4 clip;            // near, far, P[2][3], P[3][3]: -1, 0 perspective; 0, 1 orthographic
};
static_assert(sizeof(FrameBlock) == 4 * 64 + 4 * 16, "FrameBlock must match its std140 layout");

FrameBlock makeFrameBlock(const Camera& camera, int width, int height);

// Where every pass that reads the camera finds the frame block.
constexpr BindingPoint kFrameUbo{"FRAME_UBO", BindingKind::UniformBuffer, 0};

}  // namespace pbr
