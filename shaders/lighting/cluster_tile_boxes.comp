#version 450 core
// After cluster_activate.comp, one invocation per screen tile: decodes the tile's box, the union of its clusters'
// boxes, into two padded vec4 for the light pass (after the clusters', tileBoxIndex).
layout(local_size_x = 64) in;

#include "clusters.glsl"

layout(std430, binding = CLUSTER_OCCUPANCY_SSBO) readonly buffer Occupancy { uint occupancy[]; };
layout(std430, binding = CLUSTER_BOXES_SSBO) writeonly buffer Boxes { vec4 boxes[]; };

void main() {
  uint tile = gl_GlobalInvocationID.x;
  if (tile >= tileCount()) return;
  uint base = tileBoxBase(tile);
  vec3 lo, hi;
  bool occupied = occupiedBox(uvec3(occupancy[base], occupancy[base + 1u], occupancy[base + 2u]),
                              uvec3(occupancy[base + 3u], occupancy[base + 4u], occupancy[base + 5u]), lo, hi);
  uint box = 2u * tileBoxIndex(tile);
  boxes[box] = occupied ? vec4(lo, 0.0) : vec4(3.0e38);
  boxes[box + 1u] = occupied ? vec4(hi, 0.0) : vec4(-3.0e38);
}
