#version 450 core
// First pass of light assignment: where the surfaces are. Every pixel with depth grows the view-space box of its
// cluster and of its screen tile to hold its surface point, so that lights are tested against the surfaces a
// cluster holds rather than its whole froxel, and clusters without surface get no list. A pixel within 1e-3 of
// a slice boundary joins both clusters: the lighting pass computes the slice in another program, whose
// logarithm may round the other way.
layout(local_size_x = 8, local_size_y = 8) in;

#include "../common/frame.glsl"
#include "clusters.glsl"

layout(binding = SURFACE_DEPTH_UNIT) uniform sampler2D gDepth;
layout(std430, binding = CLUSTER_OCCUPANCY_SSBO) buffer Occupancy { uint occupancy[]; };

// Most pixels leave a box as it is: a plain read saves the atomic.
void keepLess(uint word, uint value) {
  if (value < occupancy[word]) atomicMin(occupancy[word], value);
}

void growBox(uint base, vec3 p) {
  keepLess(base, orderedBits(p.x));
  keepLess(base + 1u, orderedBits(p.y));
  keepLess(base + 2u, orderedBits(p.z));
  keepLess(base + 3u, ~orderedBits(p.x));
  keepLess(base + 4u, ~orderedBits(p.y));
  keepLess(base + 5u, ~orderedBits(p.z));
}

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, ivec2(frame.viewport.xy)))) return;
  float depth = texelFetch(gDepth, p, 0).r;
  if (depth <= 0.0) return;
  // The view-space point surface.glsl reconstructs.
  vec2 ndc = (vec2(p) + 0.5) * frame.viewport.zw * 2.0 - 1.0;
  float zView = -frame.projParams.w / (depth + frame.projParams.z);
  vec3 viewPos = vec3(-zView * ndc.x / frame.projParams.x, -zView * ndc.y / frame.projParams.y, zView);
  uvec2 tileXY = min(uvec2(p) / clusterGrid.dims.w, clusterGrid.dims.xy - 1u);
  uint tile = tileXY.y * clusterGrid.dims.x + tileXY.x;
  float s = sliceCoordinate(-zView);
  uint lo = clampSlice(floor(s - 1e-3)), hi = clampSlice(floor(s + 1e-3));
  growBox(tileBoxBase(tile), viewPos);
  growBox(clusterBoxBase(lo * tileCount() + tile), viewPos);
  if (hi != lo) growBox(clusterBoxBase(hi * tileCount() + tile), viewPos);
}
