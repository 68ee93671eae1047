#pragma once
#include <memory>
#include <vector>

#include <glm/vec4.hpp>

#include "core/gl_objects.hpp"
#include "core/scene.hpp"

namespace pbr {

// std430 mirror of `PointLight` in shaders/lighting/lights.glsl.
struct GpuLight {
  glm::vec4 positionRadius;
  glm::vec4 colorIntensity;  // rgb, luminous intensity I = P / (4 pi)
};
static_assert(sizeof(GpuLight) == 32, "GpuLight must match its std430 layout");

GpuLight toGpuLight(const PointLight& light);

// The frame's point lights in a shader storage buffer, reallocated only when it must grow.
class LightBuffer {
 public:
  void upload(const std::vector<PointLight>& lights);
  void bind() const;
  unsigned count() const { return count_; }
  size_t bytes() const { return buffer_ ? buffer_->size() : 0; }

 private:
  std::unique_ptr<Buffer> buffer_;
  unsigned count_ = 0;
};

}  // namespace pbr
