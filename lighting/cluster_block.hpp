#pragma once
#include <cstdint>

#include <glm/vec4.hpp>

namespace pbr {

// std140 mirror of `ClusterBlock` in shaders/lighting/clusters.glsl.
struct ClusterBlock {
  glm::uvec4 dims;     // tiles x, tiles y, depth slices, tile size in pixels
  glm::vec4 slicing;   // near, far, slice scale, slice bias
  glm::uvec4 counts;   // lights, clusters, index-list capacity, stats enabled
};
static_assert(sizeof(ClusterBlock) == 48, "ClusterBlock must match its std140 layout");

// std430 mirror of `Status` in shaders/lighting/cluster_scan.comp.
struct ClusterStatus {
  uint32_t demand;
  uint32_t nonEmpty;
  uint32_t maxPerCluster;
  uint32_t visibleLights;
  uint32_t overflowed;
  uint32_t capacity;
  uint32_t unused[2];
};
static_assert(sizeof(ClusterStatus) == 32, "ClusterStatus must match its std430 layout");

}  // namespace pbr
