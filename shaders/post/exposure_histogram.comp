#version 450 core
// The automatic exposure's meter, first step: each pixel's luminance counted in its 1/8-stop bin of log2
// luminance, in shared memory per workgroup, then once per bin into the frame's histogram.
layout(local_size_x = 16, local_size_y = 16) in;

#include "exposure_state.glsl"

layout(binding = 0) uniform sampler2D hdrIn;

shared uint localBins[METER_BINS];

void main() {
  for (uint i = gl_LocalInvocationIndex; i < METER_BINS; i += 256u) localBins[i] = 0u;
  barrier();
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (all(lessThan(p, textureSize(hdrIn, 0)))) {
    // Rec. 709 / sRGB luminance (ITU-R BT.709, item 3.3).
    float l = dot(texelFetch(hdrIn, p, 0).rgb, vec3(0.2126, 0.7152, 0.0722));
    // Black (nothing drawn) and NaN are not metered; beyond the top bin counts in it.
    if (l >= exp2(METER_LOG2_MIN)) {
      float bin = clamp((log2(l) - METER_LOG2_MIN) * METER_BINS_PER_STOP, 0.0, float(METER_BINS - 1));
      atomicAdd(localBins[uint(bin)], 1u);
    }
  }
  barrier();
  for (uint i = gl_LocalInvocationIndex; i < METER_BINS; i += 256u) {
    if (localBins[i] != 0u) atomicAdd(meter.bins[i], localBins[i]);
  }
}
