#pragma once
#include <string>

#include <nlohmann/json.hpp>

#include "app/bench/bench_report.hpp"

namespace pbr {

// A report that writeBenchJson wrote (schema "pbr-bench/1"), read back.
struct BenchReportFile {
  BenchReport report;             // provenance, settings, shard and results
  std::string sweepFingerprint;   // as the file states it
  nlohmann::json settings;        // as written, to say how two files' settings differ
  // Whether it states where each configuration's frames and passes lie on its timeline, as a trace needs
  // (timeline_start_ms, passes_start_ms): reports of builds before they were recorded do not.
  bool traceLayout = true;
};

// Reads `path` into a BenchReportFile. The summaries of each result are computed again from its timed frames,
// which the JSON holds at full precision, so that the report writes the same CSV rows and JSON configurations as
// the run that measured it. Throws SceneError with one line naming the file and what is wrong, with the JSON path
// of a bad field ("F: configurations[2].lights: expected an integer in [0, 1048576], got \"x\"").
BenchReportFile readBenchReport(const std::string& path);

}  // namespace pbr
