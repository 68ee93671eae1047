#version 450 core
// The automatic exposure's meter, second step (one invocation): the mean log2 luminance of the pixels between the
// METER_LOW_SHARE and METER_HIGH_SHARE of the histogram, mapped to the key value (Reinhard et al. 2002, "Photographic
// Tone Reproduction for Digital Images", eq. 2: exposure = key / mean luminance), as the EV100 of a camera
// (exposure = 1 / (1.2 2^EV100), core/scene/exposure.hpp); the applied exposure moves toward it; the histogram is
// cleared for the next frame.
layout(local_size_x = 1) in;

#include "exposure_state.glsl"

// x: seconds to adapt over (negative: at once), y: the EV100 before any frame is metered.
layout(location = 0) uniform vec2 adaptation;

void main() {
  float total = 0.0;
  for (int i = 0; i < METER_BINS; ++i) total += float(meter.bins[i]);
  float target = meter.metered != 0u ? meter.ev100 : adaptation.y;
  if (total > 0.0) {
    // Each bin's pixels that rank between the two shares, weighted by the bin's centre.
    float low = METER_LOW_SHARE * total, high = METER_HIGH_SHARE * total;
    float below = 0.0, weight = 0.0, sum = 0.0;
    for (int i = 0; i < METER_BINS; ++i) {
      float n = float(meter.bins[i]);
      float taken = clamp(high - below, 0.0, n) - clamp(low - below, 0.0, n);
      sum += taken * (METER_LOG2_MIN + (float(i) + 0.5) / METER_BINS_PER_STOP);
      weight += taken;
      below += n;
      meter.bins[i] = 0u;
    }
    // key / L = 1 / (1.2 2^EV100)  =>  EV100 = log2(L) - log2(1.2 key).
    if (weight > 0.0) target = sum / weight - log2(1.2 * METER_KEY);
  }
  float ev = target;
  if (meter.metered != 0u && adaptation.x >= 0.0) {
    // A brighter scene meters a higher EV100 and darkens the frame.
    ev = meter.ev100 + clamp(target - meter.ev100, -ADAPT_BRIGHTEN_EV_PER_SECOND * adaptation.x,
                             ADAPT_DARKEN_EV_PER_SECOND * adaptation.x);
  }
  meter.ev100 = ev;
  meter.exposure = 1.0 / (1.2 * exp2(ev));
  meter.targetEv100 = target;
  meter.metered = total > 0.0 || meter.metered != 0u ? 1u : 0u;
}
