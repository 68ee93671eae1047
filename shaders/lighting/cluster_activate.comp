#version 450 core
// Second pass of light assignment, one invocation per cluster: decodes the box of the surfaces it holds
// (cluster_occupancy.comp) into two padded vec4 for the light pass, grows its screen tile's box by it (decoded by
// cluster_tile_boxes.comp), and gives each cluster that holds a surface a slot: its light mask, and its place in
// the fill pass's work. Slots come from an atomic counter, so their order varies from frame to frame; a list's
// content does not depend on it. Clusters without surface get the CLUSTER_INACTIVE header (no list), and so do
// those past the slot capacity, which the lighting pass then shades by brute force (the cluster scan counts them as
// overflowed, and the capacity grows for the next frame); the others start from a count of zero.
layout(local_size_x = 64) in;

#include "clusters.glsl"

layout(std430, binding = CLUSTER_SSBO) writeonly buffer Headers { ClusterHeader headers[]; };
layout(std430, binding = CLUSTER_OCCUPANCY_SSBO) buffer Occupancy { uint occupancy[]; };
layout(std430, binding = CLUSTER_BOXES_SSBO) writeonly buffer Boxes { vec4 boxes[]; };
layout(std430, binding = CLUSTER_SLOTS_SSBO) buffer Slots { uint clusterSlots[]; };  // tile bits zeroed before
layout(std430, binding = SLOT_CLUSTERS_SSBO) buffer SlotClusters {
  uint activeCount;  // zeroed before the pass
  uint slotClusters[];
};

void main() {
  uint id = gl_GlobalInvocationID.x;
  if (id >= clusterCount()) return;
  uint base = clusterBoxBase(id);
  uvec3 minBits = uvec3(occupancy[base], occupancy[base + 1u], occupancy[base + 2u]);
  uvec3 notMaxBits = uvec3(occupancy[base + 3u], occupancy[base + 4u], occupancy[base + 5u]);
  vec3 lo, hi;
  bool occupied = occupiedBox(minBits, notMaxBits, lo, hi);
  boxes[2u * id] = occupied ? vec4(lo, 0.0) : vec4(3.0e38);
  boxes[2u * id + 1u] = occupied ? vec4(hi, 0.0) : vec4(-3.0e38);
  uint tile = id % tileCount(), slice = id / tileCount();
  if (occupied) {
    uint tileBase = tileBoxBase(tile);
    for (uint i = 0u; i < 3u; ++i) {
      atomicMin(occupancy[tileBase + i], minBits[i]);
      atomicMin(occupancy[tileBase + 3u + i], notMaxBits[i]);
    }
  }
  uint slot = occupied ? atomicAdd(activeCount, 1u) : CLUSTER_INACTIVE;
  bool slotted = slot < slotCapacity();
  clusterSlots[id] = slotted ? slot : CLUSTER_INACTIVE;
  headers[id] = slotted ? ClusterHeader(0u, 0u) : ClusterHeader(CLUSTER_INACTIVE, 0u);
  if (!slotted) return;
  slotClusters[slot] = id;
  atomicOr(clusterSlots[tileSliceBase(tile) + slice / 32u], 1u << (slice % 32u));
}
