#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "app/bench/bench_eta.hpp"
#include "app/bench/bench_run.hpp"
#include "app/bench/bench_sweep.hpp"

namespace pbr {

// A sweep's progress on stderr. The sweep renders each configuration's first frame (its estimate), then takes
// the configurations' frames in turn, a round at a time. On a terminal a bar redrawn after every frame with the
// time the sweep has left (SweepEta); a line per configuration estimated or skipped; a line per round where
// there is no terminal (a log, CI, a batch job), at most one every 30 s; at the end a line per configuration.
class BenchProgress {
 public:
  BenchProgress(std::vector<BenchConfig> configs, const BenchSettings& settings, bool terminal);
  // Configuration `index` rendered a frame; it renders one every `frameSeconds`.
  void rendered(size_t index, double frameSeconds);
  // Its first frame is rendered and its time estimated (`partial`), or it is skipped and renders no more.
  void probed(size_t index, const BenchResult& partial);
  // The sweep is in round `round` (from 1) of `rounds` of `phase` ("warm-up", "timed").
  void round(const char* phase, int round, int rounds);
  void finished(size_t index, const BenchResult& result) const;

 private:
  void redraw(size_t index) const;
  std::string left() const;

  std::vector<BenchConfig> configs_;
  SweepEta eta_;
  bool terminal_;
  std::vector<int> framesLeft_;
  int framesTotal_ = 0;
  std::string stage_ = "first frames";
  BenchClock::time_point lastLine_;
};

}  // namespace pbr
