#include "lighting/gpu_lights.hpp"

#include <glm/gtc/constants.hpp>

namespace pbr {

GpuLight toGpuLight(const PointLight& l) {
  return {glm::vec4(l.position, l.radius), glm::vec4(l.color, l.luminousPower / (4.0f * glm::pi<float>()))};
}

GpuSpotCone toGpuSpotCone(const PointLight& l) {
  if (!l.spot) return {0.0f, 0.0f, 0.0f, 1.0f};
  const SpotFalloff f = spotFalloff(*l.spot);
  return glm::vec4(l.spot->direction * f.scale, f.offset);
}

}  // namespace pbr
