#include "app/bench/trace_writer.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "core/scene/json_text.hpp"

namespace pbr {

namespace {

using Json = nlohmann::ordered_json;

Json metadata(const char* name, int pid, int tid, const Json& args) {
  return {{"name", name}, {"ph", "M"}, {"pid", pid}, {"tid", tid}, {"args", args}};
}

// Nanosecond resolution is all the clocks have; rounding keeps float noise out of the file.
double roundedUs(double us) { return std::round(us * 1e3) * 1e-3; }

Json slice(const std::string& name, const char* category, double tsUs, double durUs, int pid, int tid,
           const Json& args) {
  return {{"name", name}, {"cat", category}, {"ph", "X"}, {"ts", roundedUs(tsUs)},
          {"dur", roundedUs(std::max(durUs, 0.0))}, {"pid", pid}, {"tid", tid}, {"args", args}};
}

}  // namespace

void writeTrace(std::ostream& out, const BenchReport& report) {
  const BenchSettings& s = report.settings;
  const std::string title = "pbr bench: " + s.scene + " " + std::to_string(s.size.x) + "x" +
                            std::to_string(s.size.y) + " on " + report.provenance.get("gl_renderer");
  Json events = Json::array();
  std::set<int> named;
  for (size_t i = 0; i < report.results.size(); ++i) {
    const BenchResult& r = report.results[i];
    // A process per shard: the report's own, or in a merged report the one that measured the configuration, on
    // whose timeline (from that shard's start) its frames lie.
    const int shard = report.shard ? report.shard->index : r.shard;
    const int pid = std::max(shard, 1);
    if (named.insert(pid).second) {
      const std::string part = report.shard ? ", shard " + report.shard->text()
                                            : shard > 0 ? ", shard " + std::to_string(shard) : "";
      events.push_back(metadata("process_name", pid, 0, {{"name", title + part}}));
    }
    const int tid = static_cast<int>(i) + 1;
    events.push_back(metadata("thread_name", pid, tid, {{"name", r.config.label() + (r.skipped ? " (skipped)" : "")}}));
    events.push_back(metadata("thread_sort_index", pid, tid, {{"sort_index", tid}}));
    for (const FrameTiming& f : r.frames) {
      const double frameUs = (r.timelineStartMs + f.startMs - r.frames.front().startMs) * 1e3;
      const double frameDurUs = f.gpuMs * 1e3;
      events.push_back(
          slice("frame", "frame", frameUs, frameDurUs, pid, tid, {{"frame", f.frame}, {"cpu_ms", f.cpuMs}}));
      for (const PassTiming& p : f.passes) {
        // Clamped so that rounding never lets a pass poke out of its frame, which trace viewers reject as bad nesting.
        const double startUs = std::min(p.startMs * 1e3, frameDurUs);
        events.push_back(slice(p.name, "pass", frameUs + startUs, std::min(p.ms * 1e3, frameDurUs - startUs), pid,
                               tid, {{"frame", f.frame}}));
      }
    }
  }
  Json other = Json::object();
  for (const auto& [key, value] : report.provenance.entries) other[key] = value;
  const Json doc = {{"traceEvents", events}, {"displayTimeUnit", "ms"}, {"otherData", other}};
  out << jsonText(doc) << "\n";
}

}  // namespace pbr
