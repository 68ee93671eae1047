#version 450 core
// First pass of light assignment: every pixel of the G-buffer with depth occupies its clusters
// (cluster_occupancy.glsl).
layout(local_size_x = 8, local_size_y = 8) in;

#include "cluster_occupancy.glsl"

layout(binding = SURFACE_DEPTH_UNIT) uniform sampler2D gDepth;

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, ivec2(frame.viewport.xy)))) return;
  float depth = texelFetch(gDepth, p, 0).r;
  if (depth > 0.0) occupy(uvec2(p), depth);
}
