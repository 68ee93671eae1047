#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "app/bench/bench_sweep.hpp"

namespace pbr {

// How long the rest of a sweep will take, from what it has measured so far. A configuration renders warm-up +
// timed + 1 frames; its time per frame is predicted along the light count from configurations measured with the
// same culling mode and shading model: on the line through the two measured light counts nearest it, or in
// proportion to the light count from one; failing those, from the measured configuration (or the running one)
// nearest in light count. One predicted over --max-seconds costs one frame, as the sweep skips it after that.
class SweepEta {
 public:
  SweepEta(std::vector<BenchConfig> configs, const BenchSettings& settings);

  // Records configuration `index`'s measurement.
  void finished(size_t index, const BenchResult& result);
  // Seconds left in the sweep while configuration `index` has rendered `done` of its frames in `elapsedSeconds`
  // (done >= 1): the rest of its frames at its running rate, then the configurations after it as predicted.
  double remainingSeconds(size_t index, int done, double elapsedSeconds) const;
  // Seconds left once configuration `index` has finished.
  double remainingAfter(size_t index) const;

 private:
  struct Measured {
    BenchConfig config;
    double frameSeconds;
  };
  double predictedSeconds(const BenchConfig& config, const std::vector<Measured>& measured) const;

  std::vector<BenchConfig> configs_;
  int framesPerConfig_;
  double maxSeconds_;
  std::vector<Measured> measured_;
};

// "42 s", "3 min 05 s", "2 h 07 min".
std::string formatDuration(double seconds);

}  // namespace pbr
