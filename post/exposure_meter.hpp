#pragma once
#include <cstdint>
#include <optional>

#include "core/gl/gl_objects.hpp"
#include "core/gl/program_cache.hpp"
#include "post/post_bindings.hpp"

namespace pbr {

// Automatic exposure (--exposure auto), metered on the GPU from the frame's HDR radiance before exposure: a
// histogram of log2 luminance in 1/8-stop bins (shaders/post/exposure_histogram.comp), whose mean between the 10th
// and 90th percentiles of the metered pixels is mapped to Reinhard's key value 0.18
// (shaders/post/exposure_adapt.comp). Percentile bounds rather than a plain log-average, as Filament and Bevy
// meter: a few light sources or a bright sky in view do not darken the frame, and dark corners do not blow it out.
// Black pixels (below 2^-24 cd/m^2: the background where nothing is drawn) are not metered. Bins of an eighth of a
// stop make a scene lit 2^k times brighter meter exactly k stops higher.
constexpr int kMeterLog2Min = -24;  // the bottom of the first bin: darker is black, not metered
constexpr int kMeterLog2Max = 24;   // the top of the last bin: brighter counts in it
constexpr int kMeterBinsPerStop = 8;
constexpr int kMeterBins = (kMeterLog2Max - kMeterLog2Min) * kMeterBinsPerStop;
constexpr float kMeterLowShare = 0.10f;     // the share of metered pixels left out at the dark end
constexpr float kMeterHighShare = 0.90f;    // and above this share, at the bright end
constexpr float kMeterKey = 0.18f;          // what the metered mean luminance shows as, before the tone curve
// The viewer's adaptation: at most this many stops per second, as Bevy's defaults (speed_brighten 3, speed_darken 1).
constexpr float kAdaptBrightenEvPerSecond = 3.0f;
constexpr float kAdaptDarkenEvPerSecond = 1.0f;

// std430 mirror of `ExposureState` in shaders/post/exposure_state.glsl.
struct ExposureState {
  float ev100;        // the exposure the post pass applies, as a camera's EV100
  float exposure;     // 1 / (1.2 * 2^ev100), what radiance is multiplied by (core/scene/exposure.hpp)
  float targetEv100;  // what the last metered frame asked for; ev100 moves toward it
  uint32_t metered;   // 0 until a frame has been metered
  uint32_t bins[kMeterBins];
};
static_assert(sizeof(ExposureState) == 16 + 4 * kMeterBins, "ExposureState must match its std430 layout");

// What a frame's metering says, read back for reports.
struct MeteredExposure {
  float ev100 = 0.0f;        // applied to the frame
  float targetEv100 = 0.0f;  // what the frame itself metered (ev100 once converged)
};

class ExposureMeter {
 public:
  // The programs are compiled on first use: frames with a fixed exposure never build them.
  explicit ExposureMeter(ProgramCache& programs);
  // Meters `hdr` and moves the applied exposure toward it: at once when `adaptSeconds` is not finite or no frame
  // was metered before, else by at most kAdaptBrighten/DarkenEvPerSecond times `adaptSeconds`. A frame without a
  // metered pixel keeps the exposure it had, `initialEv100` before any.
  void meter(const Texture& hdr, float adaptSeconds, float initialEv100);
  // Binds the state at kExposureSsbo for the post pass.
  void bind() const;
  // The last metering; waits for the GPU.
  MeteredExposure read() const;
  // With no argument the next metering sets the exposure at once; with one, the exposure adapts from `fromEv100`.
  void reset(std::optional<float> fromEv100 = std::nullopt);
  // The defines of both metering programs: the constants above and the binding point.
  static ShaderDefines defines();

 private:
  ProgramCache& programs_;
  const Program* histogram_ = nullptr;  // both compiled by the first metering
  const Program* adapt_ = nullptr;
  Buffer state_;
};

}  // namespace pbr
