#pragma once
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "core/gl/gl_objects.hpp"
#include "core/gl/uniform_buffer.hpp"
#include "core/scene/scene.hpp"
#include "lighting/gpu_lights.hpp"

namespace pbr {

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
  LightKinds kinds() const { return {hasSpots_, directionalCount_}; }
  size_t bytes() const { return (buffer_ ? buffer_->size() : 0) + (cones_ ? cones_->size() : 0); }

 private:
  std::unique_ptr<Buffer> buffer_;
  std::unique_ptr<Buffer> cones_;  // only while the frame has spot lights
  std::vector<uint32_t> order_;    // per buffer index, the scene's
  bool hasSpots_ = false;
  uint32_t directionalCount_ = 0;
  unsigned count_ = 0;
  UniformBuffer<DirectionalLightBlock> directionalBlock_{"lights.directional", DirectionalLightBlock{}};
};

}  // namespace pbr
