#version 450 core
// View-space AABBs of the froxels: screen tiles x exponential depth slices. Runs when the projection or the
// resolution changes, not every frame.
layout(local_size_x = 64) in;

#include "../common/frame.glsl"
#include "clusters.glsl"

layout(std430, binding = CLUSTER_BOUNDS_SSBO) writeonly buffer Bounds { ClusterBounds bounds[]; };

float sliceDepth(uint k) {
  float nearZ = clusterGrid.slicing.x, farZ = clusterGrid.slicing.y;
  return nearZ * pow(farZ / nearZ, float(k) / float(clusterGrid.dims.z));
}

void main() {
  uint index = gl_GlobalInvocationID.x;
  if (index >= clusterCount()) return;
  uvec3 c = clusterCoords(index);
  vec2 pixelLo = vec2(c.xy * clusterGrid.dims.w);
  vec2 pixelHi = min(vec2((c.xy + 1u) * clusterGrid.dims.w), frame.viewport.xy);
  vec2 ndcLo = pixelLo * frame.viewport.zw * 2.0 - 1.0;
  vec2 ndcHi = pixelHi * frame.viewport.zw * 2.0 - 1.0;
  float zNear = sliceDepth(c.z);
  float zFar = sliceDepth(c.z + 1u);
  vec3 lo = vec3(3.0e38), hi = vec3(-3.0e38);
  for (int i = 0; i < 4; ++i) {
    vec2 ndc = vec2((i & 1) != 0 ? ndcHi.x : ndcLo.x, (i & 2) != 0 ? ndcHi.y : ndcLo.y);
    vec3 dir = vec3(ndc.x / frame.projParams.x, ndc.y / frame.projParams.y, -1.0);
    lo = min(lo, min(dir * zNear, dir * zFar));
    hi = max(hi, max(dir * zNear, dir * zFar));
  }
  // Pixels reach their slice through log() in float and their position through the depth buffer: widen each
  // box by a relative margin far above those rounding errors, so a pixel is always inside its cluster's box
  // and a light missing the box can contribute nothing to it.
  vec3 extent = max(abs(lo), abs(hi));
  float pad = 1e-4 * max(extent.x, max(extent.y, extent.z)) + 1e-6;
  bounds[index] = ClusterBounds(vec4(lo - pad, 0.0), vec4(hi + pad, 0.0));
}
