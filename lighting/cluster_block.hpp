#pragma once
#include <cstdint>

#include <glm/vec4.hpp>

namespace pbr {

// std140 mirror of `ClusterBlock` in shaders/lighting/clusters.glsl.
struct ClusterBlock {
  glm::uvec4 dims;     // tiles x, tiles y, depth slices, tile size in pixels
  glm::vec4 slicing;   // near, margin of a box past its slice (in slices), slice scale, slice bias
  glm::uvec4 counts;   // lights, clusters, index-list capacity, stats enabled
  glm::uvec4 window;   // lights of the masks: first, end; mask words per slot, slot capacity
};
static_assert(sizeof(ClusterBlock) == 64, "ClusterBlock must match its std140 layout");

// std430 mirrors of the per-cluster records in shaders/lighting/clusters.glsl.
struct ClusterHeader {
  uint32_t offset;  // first entry in the light-index list
  uint32_t count;
};
static_assert(sizeof(ClusterHeader) == 8, "ClusterHeader must match its std430 layout");
// Words per occupancy box in shaders/lighting/clusters.glsl (clusterBoxBase): a view-space AABB as ordered bits.
constexpr uint32_t kOccupancyWords = 6;
// Per cluster and tile, cluster_activate.comp's decoded box: two vec4 (minimum, maximum corner).
constexpr uint32_t kBoxBytes = 32;

// std430 mirror of `Status` in shaders/lighting/cluster_scan.comp.
struct ClusterStatus {
  uint32_t demand;
  uint32_t nonEmpty;
  uint32_t maxPerCluster;
  uint32_t visibleLights;
  uint32_t overflowed;
  uint32_t capacity;
  uint32_t activeClusters;  // clusters holding a surface
  uint32_t unslotted;       // of those, clusters beyond the masks' slot capacity (shaded by brute force)
};
static_assert(sizeof(ClusterStatus) == 32, "ClusterStatus must match its std430 layout");

}  // namespace pbr
