#include "core/io/frame_timing.hpp"

#include <stdexcept>

#include "core/io/context_info.hpp"

namespace pbr {

TimingMode chooseTimingMode(const std::string& requested, const std::string& glRenderer) {
  if (requested == "gpu") return TimingMode::GpuQueries;
  if (requested == "serial") return TimingMode::Serializing;
  if (requested == "auto") return isSoftwareRenderer(glRenderer) ? TimingMode::Serializing : TimingMode::GpuQueries;
  throw std::invalid_argument("unknown timing mode '" + requested + "' (expected auto, gpu or serial)");
}

const char* describe(TimingMode mode) {
  return mode == TimingMode::GpuQueries ? "gpu timer queries" : "serializing (glFinish + CPU clock)";
}

double FrameTiming::pass(const std::string& name) const {
  double total = 0.0;
  for (const PassTiming& p : passes) {
    if (p.name == name) total += p.ms;
  }
  return total;
}

}  // namespace pbr
