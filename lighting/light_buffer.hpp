#pragma once
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/vec4.hpp>

#include "core/gl/gl_objects.hpp"
#include "core/gl/uniform_buffer.hpp"
#include "core/scene/scene.hpp"

namespace pbr {

// std430 (and std140) mirror of `PointLight` in shaders/lighting/lights.glsl.
struct GpuLight {
  glm::vec4 positionRadius;
  glm::vec4 colorIntensity;  // rgb, luminous intensity I = P / (4 pi)
};
static_assert(sizeof(GpuLight) == 32, "GpuLight must match its std430 layout");
static_assert(offsetof(GpuLight, colorIntensity) == 16, "GpuLight must match its std430 layout");

GpuLight toGpuLight(const PointLight& light);

// Mirror of a light's entry in `spotCones` and `windowCones` (shaders/lighting/lights.glsl): the spot light's axis
// times its falloff's scale, and the offset (SpotFalloff); a point light's (0, 0, 0, 1) leaves it unmasked.
using GpuSpotCone = glm::vec4;
GpuSpotCone toGpuSpotCone(const PointLight& light);

// std140 mirror of `DirectionalLightBlock` in shaders/lighting/directional_lights.glsl.
struct GpuDirectionalLight {
  glm::vec4 toLight;           // xyz: unit direction towards the light
  glm::vec4 colorIlluminance;  // rgb, illuminance E in lux
};
struct DirectionalLightBlock {
  glm::uvec4 count;  // x: lights in use
  GpuDirectionalLight lights[kMaxDirectionalLights];
};
static_assert(sizeof(GpuDirectionalLight) == 32, "GpuDirectionalLight must match its std140 layout");
static_assert(offsetof(DirectionalLightBlock, lights) == 16, "DirectionalLightBlock must match its std140 layout");
static_assert(sizeof(DirectionalLightBlock) == 16 + 32 * kMaxDirectionalLights, "DirectionalLightBlock: std140");

// Lights in the largest uniform-buffer window the lighting pass reads (64 KiB, the most llvmpipe and most GPUs
// allow one uniform block). The buffer holds whole windows, so that every window bound is backed in full.
constexpr uint32_t kLightWindowMax = 2048;

// The frame's point and spot lights in one buffer, in the order lightBufferOrder gives them (light_order.hpp), read
// as a storage buffer (cluster assignment, clustered lighting) and, a window at a time, as a uniform buffer
// (lighting every light), reallocated only when it must grow; with spot lights among them, their cones in a second
// buffer of the same layout; and the directional lights in a uniform block of their own, which no culling touches.
// A frame without spot lights neither uploads nor reads cones (the SPOT_LIGHTS permutations).
class LightBuffer {
 public:
  // Point and spot lights, and directional lights, are replaced separately: replacing one leaves the other.
  void uploadPoints(const std::vector<PointLight>& lights);
  void uploadDirectional(const std::vector<DirectionalLight>& directional);
  void bind() const;
  void bindDirectional() const;
  // Lights [first, first + lights) as the LightWindow uniform block; `first` a multiple of `lights`, a power of
  // two no larger than kLightWindowMax.
  void bindWindow(uint32_t first, uint32_t lights) const;
  unsigned count() const { return count_; }
  // The scene's index of the light at `bufferIndex`: cluster lists (LightClusters::readLists) hold buffer indices.
  uint32_t sceneIndex(uint32_t bufferIndex) const { return order_[bufferIndex]; }
  const std::vector<uint32_t>& order() const { return order_; }  // per buffer index, the scene's
  bool hasSpotLights() const { return hasSpots_; }
  size_t bytes() const { return (buffer_ ? buffer_->size() : 0) + (cones_ ? cones_->size() : 0); }

 private:
  std::unique_ptr<Buffer> buffer_;
  std::unique_ptr<Buffer> cones_;  // only while the frame has spot lights
  std::vector<uint32_t> order_;    // per buffer index, the scene's
  bool hasSpots_ = false;
  unsigned count_ = 0;
  UniformBuffer<DirectionalLightBlock> directionalBlock_{"lights.directional", DirectionalLightBlock{}};
};

}  // namespace pbr
