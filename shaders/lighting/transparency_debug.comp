#version 450 core
// The BLEND layers each pixel shows in front of its opaque surface, as TransparencyDebugPass counted them, on the
// heat ramp from 0 to MAX_SHOWN_LAYERS and more, with its legend; pixels without a layer show the no-data pattern.
layout(local_size_x = 8, local_size_y = 8) in;

#include "../common/frame.glsl"
#include "heat.glsl"
#include "legend.glsl"

layout(binding = OIT_ACCUMULATION_UNIT) uniform sampler2D layers;  // R32F counts
layout(rgba8, binding = 0) uniform writeonly image2D ldr;

vec3 legendRamp(float t) { return heat(t); }

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = ivec2(frame.viewport.xy);
  if (any(greaterThanEqual(p, size))) return;
  float count = texelFetch(layers, p, 0).r;
  vec3 color = count < 0.5 ? noDataPattern(p) : heat(count / float(MAX_SHOWN_LAYERS));
  imageStore(ldr, p, vec4(drawLegend(p, size, color), 1.0));
}
