#include "lighting/light_buffer.hpp"

#include <glm/gtc/constants.hpp>

#include "lighting/lighting_bindings.hpp"

namespace pbr {

GpuLight toGpuLight(const PointLight& l) {
  return {glm::vec4(l.position, l.radius), glm::vec4(l.color, l.luminousPower / (4.0f * glm::pi<float>()))};
}

void LightBuffer::upload(const std::vector<PointLight>& lights) {
  std::vector<GpuLight> packed;
  packed.reserve(lights.size());
  for (const PointLight& l : lights) packed.push_back(toGpuLight(l));
  const size_t bytes = packed.size() * sizeof(GpuLight);
  if (!buffer_ || buffer_->size() < bytes) buffer_ = std::make_unique<Buffer>(bytes);
  buffer_->upload(packed.data(), bytes);
  count_ = static_cast<unsigned>(lights.size());
}

void LightBuffer::bind() const {
  if (buffer_) buffer_->bindBase(GL_SHADER_STORAGE_BUFFER, lighting_binding::kLightSsbo.index);
}

}  // namespace pbr
