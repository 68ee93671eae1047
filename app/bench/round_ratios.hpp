#pragma once
#include <ostream>
#include <vector>

#include "app/bench/bench_report.hpp"

namespace pbr {

// A configuration's times over those of the same culling and model at the sweep's smallest light count, round by
// round: a sweep taken in turn renders frame k of every configuration in round k, so each round's ratio is
// measured under the same machine load, where a ratio of medians mixes minutes that may have run at different
// speeds. Empty where the report was not taken in turn.
struct RoundRatios {
  const BenchResult* result = nullptr;
  const BenchResult* base = nullptr;  // the same culling and model at the smallest light count
  std::vector<double> frame;          // frame time, per round
  std::vector<double> cluster;        // the cluster pass, per round; empty for brute force
};

// For every measured configuration above the smallest light count whose base was measured in the same run (in a
// merged report, by the same shard).
std::vector<RoundRatios> roundRatios(const BenchReport& report);

// The ratios' median and range per configuration, as a table under the bench's; nothing when there are none.
void printRoundRatios(std::ostream& out, const BenchReport& report);

}  // namespace pbr
