#include "core/scene/frame_block.hpp"

#include <glm/matrix.hpp>

namespace pbr {

FrameBlock makeFrameBlock(const Camera& camera, int width, int height) {
  FrameBlock b{};
  b.view = camera.view();
  b.projection = camera.projection(static_cast<float>(width) / static_cast<float>(height));
  b.viewProjection = b.projection * b.view;
  b.inverseView = glm::inverse(b.view);
  b.cameraPosition = glm::vec4(camera.position, 1.0f);
  b.viewport = glm::vec4(width, height, 1.0f / width, 1.0f / height);
  b.projParams = glm::vec4(b.projection[0][0], b.projection[1][1], b.projection[2][2], b.projection[3][2]);
  b.clip = glm::vec4(camera.nearPlane, camera.farPlane, b.projection[2][3], b.projection[3][3]);
  return b;
}

}  // namespace pbr
