#version 450 core
// The occupied clusters alone, for a read-back by the CPU (LightClusters::occupiedBoxes, shadow planning): one
// invocation per cluster appends its index and its six occupancy words (cluster_occupancy.comp) to a list, so that
// the read-back carries the few thousand occupied clusters of a frame, not every cluster of the grid. The order of
// the entries varies from frame to frame; the reader sorts them by cluster.
layout(local_size_x = 64) in;

#include "clusters.glsl"

layout(std430, binding = CLUSTER_OCCUPANCY_SSBO) readonly buffer Occupancy { uint occupancy[]; };
layout(std430, binding = OCCUPIED_CLUSTERS_SSBO) buffer Occupied {
  uvec4 occupiedCount;  // x: entries; zeroed before the pass
  uvec4 entries[];      // two per cluster: (cluster, minimum's three words), (maximum's three words, 0)
};

void main() {
  uint cluster = gl_GlobalInvocationID.x;
  if (cluster >= clusterCount()) return;
  uint base = clusterBoxBase(cluster);
  if (occupancy[base] == 0xFFFFFFFFu) return;
  uint i = atomicAdd(occupiedCount.x, 1u);
  entries[2u * i] = uvec4(cluster, occupancy[base], occupancy[base + 1u], occupancy[base + 2u]);
  entries[2u * i + 1u] = uvec4(occupancy[base + 3u], occupancy[base + 4u], occupancy[base + 5u], 0u);
}
