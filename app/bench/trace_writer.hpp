#pragma once
#include <ostream>

#include "app/bench/bench_report.hpp"

namespace pbr {

// Chrome trace-event JSON (opens in Perfetto and chrome://tracing): one thread per configuration, named after
// it, on which every timed frame is a "frame" slice holding one slice per pass. Configurations follow each
// other as they ran; times are microseconds on the timing clock of the report's provenance. A merged report
// (pbr bench-merge) has a process per shard, each on its own timeline from that shard's start.
void writeTrace(std::ostream& out, const BenchReport& report);

}  // namespace pbr
