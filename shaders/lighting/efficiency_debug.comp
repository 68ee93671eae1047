#version 450 core
// The culling efficiency of each pixel in place of the final frame: light-pixel pairs that contribute over pairs
// evaluated, as the lighting pass counted them (LIGHTING_PAIR_IMAGE), on the heat ramp from 0 to 1, with its legend.
// Pixels where no pair was evaluated (no surface, or a cluster without lights) show the no-data pattern.
layout(local_size_x = 8, local_size_y = 8) in;

#include "../common/frame.glsl"
#include "heat.glsl"
#include "legend.glsl"

layout(rg32ui, binding = PAIR_COUNT_IMAGE) uniform readonly uimage2D pairCounts;  // evaluated, contributing
layout(rgba8, binding = 0) uniform writeonly image2D ldr;

vec3 legendRamp(float t) {
  return heat(t);
}

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = ivec2(frame.viewport.xy);
  if (any(greaterThanEqual(p, size))) return;
  uvec2 pairs = imageLoad(pairCounts, p).xy;
  vec3 color = pairs.x == 0u ? noDataPattern(p) : heat(float(pairs.y) / float(pairs.x));
  imageStore(ldr, p, vec4(drawLegend(p, size, color), 1.0));
}
