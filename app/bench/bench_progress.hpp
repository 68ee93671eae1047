#pragma once
#include <cstddef>

#include "app/bench/bench_sweep.hpp"

namespace pbr {

// A sweep's progress on stderr: on a terminal a bar redrawn after every frame above which each finished
// configuration leaves a line; otherwise (a log, CI) just the line per configuration.
class BenchProgress {
 public:
  BenchProgress(size_t configs, bool terminal) : configs_(configs), terminal_(terminal) {}
  void frame(size_t index, const BenchConfig& config, int done, int total) const;
  void finished(size_t index, const BenchResult& result) const;

 private:
  size_t configs_;
  bool terminal_;
};

}  // namespace pbr
