#pragma once
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "app/bench/bench_sweep.hpp"

namespace pbr {

// How long the rest of a sweep will take, from what it has measured so far. A configuration renders warm-up +
// timed + 1 frames; one not yet measured is predicted along the light count from configurations measured with
// the same culling mode and shading model: on the line through the two measured light counts nearest it, or in
// proportion to the light count from one; failing those, from the measured configuration nearest in light
// count. One predicted over --max-seconds costs one frame, as the sweep skips it after that.
class SweepEta {
 public:
  SweepEta(std::vector<BenchConfig> configs, const BenchSettings& settings);

  // Configuration `index` renders a frame in `frameSeconds`.
  void measured(size_t index, double frameSeconds);
  // Seconds left while configuration i has framesLeft[i] frames to render, at its measured rate, or as predicted
  // while it has none.
  double remainingSeconds(const std::vector<int>& framesLeft) const;
  int framesPerConfig() const { return framesPerConfig_; }

 private:
  struct Measured {
    BenchConfig config;
    double frameSeconds;
  };
  double predictedSeconds(const BenchConfig& config, const std::vector<const Measured*>& measured) const;

  std::vector<BenchConfig> configs_;
  int framesPerConfig_;
  double maxSeconds_;
  std::vector<std::optional<double>> frameSeconds_;  // per configuration, once measured
};

// "42 s", "3 min 05 s", "2 h 07 min".
std::string formatDuration(double seconds);

}  // namespace pbr
