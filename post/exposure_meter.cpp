#include "post/exposure_meter.hpp"

#include <cmath>
#include <cstddef>
#include <string>

#include "core/scene/exposure.hpp"

namespace pbr {

ShaderDefines ExposureMeter::defines() {
  return concat({{"METER_BINS", std::to_string(kMeterBins)},
                 {"METER_LOG2_MIN", std::to_string(kMeterLog2Min) + ".0"},
                 {"METER_BINS_PER_STOP", std::to_string(kMeterBinsPerStop) + ".0"},
                 {"METER_LOW_SHARE", std::to_string(kMeterLowShare)},
                 {"METER_HIGH_SHARE", std::to_string(kMeterHighShare)},
                 {"METER_KEY", std::to_string(kMeterKey)},
                 {"ADAPT_BRIGHTEN_EV_PER_SECOND", std::to_string(kAdaptBrightenEvPerSecond)},
                 {"ADAPT_DARKEN_EV_PER_SECOND", std::to_string(kAdaptDarkenEvPerSecond)}},
                bindingDefines({kExposureSsbo}));
}

ExposureMeter::ExposureMeter(ProgramCache& programs)
    : programs_(programs), state_("exposure.state", sizeof(ExposureState)) {
  reset();
}

void ExposureMeter::reset(std::optional<float> fromEv100) {
  ExposureState state{};
  if (fromEv100) {
    state.ev100 = state.targetEv100 = *fromEv100;
    state.exposure = float(exposureFromEv100(*fromEv100));
    state.metered = 1;
  }
  state_.upload(&state, sizeof state);
}

void ExposureMeter::meter(const Texture& hdr, float adaptSeconds, float initialEv100) {
  if (!histogram_) {
    histogram_ = &programs_.compute("post/exposure_histogram.comp", defines());
    adapt_ = &programs_.compute("post/exposure_adapt.comp", defines());
  }
  state_.bindBase(GL_SHADER_STORAGE_BUFFER, kExposureSsbo.index);
  histogram_->use();
  glBindTextureUnit(0, hdr.id());
  glDispatchCompute(static_cast<GLuint>((hdr.width() + 15) / 16), static_cast<GLuint>((hdr.height() + 15) / 16), 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  adapt_->use();
  // location 0: x seconds to adapt over (negative: at once), y the EV100 before any metering.
  glUniform2f(0, std::isfinite(adaptSeconds) ? adaptSeconds : -1.0f, initialEv100);
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void ExposureMeter::bind() const { state_.bindBase(GL_SHADER_STORAGE_BUFFER, kExposureSsbo.index); }

MeteredExposure ExposureMeter::read() const {
  ExposureState state{};  // its head only: the bins are the next frame's
  glGetNamedBufferSubData(state_.id(), 0, GLsizeiptr(offsetof(ExposureState, bins)), &state);
  return {state.ev100, state.targetEv100};
}

}  // namespace pbr
