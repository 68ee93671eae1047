#include "lighting/light_buffer.hpp"

#include <glm/gtc/constants.hpp>

#include <stdexcept>
#include <string>

#include "lighting/lighting_bindings.hpp"
#include "core/context.hpp"

namespace pbr {

GpuLight toGpuLight(const PointLight& l) {
  return {glm::vec4(l.position, l.radius), glm::vec4(l.color, l.luminousPower / (4.0f * glm::pi<float>()))};
}

void LightBuffer::upload(const std::vector<PointLight>& lights) {
  if (lights.size() > kSoftwareRendererMaxLights) {
    const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    if (renderer && isSoftwareRenderer(renderer)) {
      throw std::runtime_error(std::to_string(lights.size()) + " lights are more than " + renderer + " can shade (at most " +
                               std::to_string(kSoftwareRendererMaxLights) + ": it stops shader loops after 65535 iterations)");
    }
  }
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
