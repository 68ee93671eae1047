#include "lighting/light_buffer.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "lighting/light_order.hpp"
#include "lighting/lighting_bindings.hpp"

namespace pbr {

void LightBuffer::uploadDirectional(const std::vector<DirectionalLight>& directional) {
  if (directional.size() > kMaxDirectionalLights) {
    throw std::logic_error(std::to_string(directional.size()) + " directional lights, more than the " +
                           std::to_string(kMaxDirectionalLights) + " shaded (validateScene refuses them)");
  }
  DirectionalLightBlock block{};
  for (size_t i = 0; i < directional.size(); ++i) {
    const DirectionalLight& d = directional[i];
    block.lights[i] = {glm::vec4(-d.direction, 0.0f), glm::vec4(d.color, d.illuminance)};
  }
  directionalBlock_.update(block);
  directionalCount_ = uint32_t(directional.size());
}

void LightBuffer::uploadPoints(const std::vector<PointLight>& lights) {
  // Zero lights past the count: a window's tail is never read, but it is backed.
  const size_t windows = std::max<size_t>(1, (lights.size() + kLightWindowMax - 1) / kLightWindowMax);
  order_ = lightBufferOrder(lights);
  std::vector<GpuLight> packed(windows * kLightWindowMax, GpuLight{});
  for (size_t i = 0; i < lights.size(); ++i) packed[i] = toGpuLight(lights[order_[i]]);
  const size_t bytes = packed.size() * sizeof(GpuLight);
  if (!buffer_ || buffer_->size() < bytes) buffer_ = std::make_unique<Buffer>("lights.points", bytes);
  buffer_->upload(packed.data(), bytes);
  count_ = static_cast<unsigned>(lights.size());

  hasSpots_ = std::any_of(lights.begin(), lights.end(), [](const PointLight& l) { return l.spot.has_value(); });
  if (!hasSpots_) {
    cones_.reset();
    return;
  }
  std::vector<GpuSpotCone> cones(packed.size(), GpuSpotCone(0.0f));
  for (size_t i = 0; i < lights.size(); ++i) cones[i] = toGpuSpotCone(lights[order_[i]]);
  const size_t coneBytes = cones.size() * sizeof(GpuSpotCone);
  if (!cones_ || cones_->size() < coneBytes) cones_ = std::make_unique<Buffer>("lights.spotCones", coneBytes);
  cones_->upload(cones.data(), coneBytes);
}

void LightBuffer::bind() const {
  if (buffer_) buffer_->bindBase(GL_SHADER_STORAGE_BUFFER, lighting_binding::kLightSsbo.index);
  if (hasSpots_) cones_->bindBase(GL_SHADER_STORAGE_BUFFER, lighting_binding::kSpotConeSsbo.index);
}

void LightBuffer::bindDirectional() const {
  directionalBlock_.bind(lighting_binding::kDirectionalLightUbo.index);
}

void LightBuffer::bindWindow(uint32_t first, uint32_t lights) const {
  if (buffer_) {
    buffer_->bindRange(GL_UNIFORM_BUFFER, lighting_binding::kLightWindowUbo.index, size_t(first) * sizeof(GpuLight),
                       size_t(lights) * sizeof(GpuLight));
  }
  if (hasSpots_) {
    cones_->bindRange(GL_UNIFORM_BUFFER, lighting_binding::kSpotWindowUbo.index, size_t(first) * sizeof(GpuSpotCone),
                      size_t(lights) * sizeof(GpuSpotCone));
  }
}

}  // namespace pbr
