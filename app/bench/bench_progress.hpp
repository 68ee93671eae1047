#pragma once
#include <cstddef>
#include <vector>

#include "app/bench/bench_eta.hpp"
#include "app/bench/bench_run.hpp"
#include "app/bench/bench_sweep.hpp"

namespace pbr {

// A sweep's progress on stderr: on a terminal a bar redrawn after every frame, with the time the sweep has left
// (SweepEta), above which each finished configuration leaves a line; otherwise (a log, CI, a batch job) just the
// line per configuration, which also says the time left.
class BenchProgress {
 public:
  BenchProgress(std::vector<BenchConfig> configs, const BenchSettings& settings, bool terminal);
  // Starts the clock of the next configuration.
  void started();
  void frame(size_t index, int done, int total) const;
  void finished(size_t index, const BenchResult& result);

 private:
  std::vector<BenchConfig> configs_;
  SweepEta eta_;
  bool terminal_;
  BenchClock::time_point configStart_;
};

}  // namespace pbr
