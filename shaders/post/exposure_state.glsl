// The automatic exposure's state (mirrors pbr::ExposureState, post/exposure_meter.hpp): the exposure applied, as
// EV100 and as the multiplier, and the histogram of the frame being metered.
layout(std430, binding = EXPOSURE_SSBO) buffer ExposureState {
  float ev100;
  float exposure;
  float targetEv100;
  uint metered;
  uint bins[METER_BINS];
} meter;
// Bin i holds log2 luminance in [METER_LOG2_MIN + i / METER_BINS_PER_STOP, ... + (i + 1) / METER_BINS_PER_STOP),
// both defines of ExposureMeter::defines(); the post pass reads the state but not the bins.
