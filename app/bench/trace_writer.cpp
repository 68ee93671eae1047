#include "app/bench/trace_writer.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <nlohmann/json.hpp>

#include "core/json_text.hpp"

namespace pbr {

namespace {

using Json = nlohmann::ordered_json;
constexpr int kPid = 1;

Json metadata(const char* name, int tid, const Json& args) {
  return {{"name", name}, {"ph", "M"}, {"pid", kPid}, {"tid", tid}, {"args", args}};
}

// Nanosecond resolution is all the clocks have; rounding keeps float noise out of the file.
double roundedUs(double us) { return std::round(us * 1e3) * 1e-3; }

Json slice(const std::string& name, const char* category, double tsUs, double durUs, int tid, const Json& args) {
  return {{"name", name}, {"cat", category}, {"ph", "X"}, {"ts", roundedUs(tsUs)},
          {"dur", roundedUs(std::max(durUs, 0.0))}, {"pid", kPid}, {"tid", tid}, {"args", args}};
}

}  // namespace

void writeTrace(std::ostream& out, const BenchReport& report) {
  const BenchSettings& s = report.settings;
  Json events = Json::array();
  events.push_back(metadata("process_name", 0,
                            {{"name", "pbr bench: " + s.scene + " " + std::to_string(s.size.x) + "x" +
                                          std::to_string(s.size.y) + " on " + report.provenance.get("gl_renderer") +
                                          (report.shard ? ", shard " + report.shard->text() : "")}}));
  for (size_t i = 0; i < report.results.size(); ++i) {
    const BenchResult& r = report.results[i];
    const int tid = static_cast<int>(i) + 1;
    events.push_back(metadata("thread_name", tid, {{"name", r.config.label() + (r.skipped ? " (skipped)" : "")}}));
    events.push_back(metadata("thread_sort_index", tid, {{"sort_index", tid}}));
    for (const FrameTiming& f : r.frames) {
      const double frameUs = (r.timelineStartMs + f.startMs - r.frames.front().startMs) * 1e3;
      const double frameDurUs = f.gpuMs * 1e3;
      events.push_back(slice("frame", "frame", frameUs, frameDurUs, tid, {{"frame", f.frame}, {"cpu_ms", f.cpuMs}}));
      for (const PassTiming& p : f.passes) {
        // Clamped so that rounding never lets a pass poke out of its frame, which trace viewers reject as bad nesting.
        const double startUs = std::min(p.startMs * 1e3, frameDurUs);
        events.push_back(slice(p.name, "pass", frameUs + startUs, std::min(p.ms * 1e3, frameDurUs - startUs), tid,
                               {{"frame", f.frame}}));
      }
    }
  }
  Json other = Json::object();
  for (const auto& [key, value] : report.provenance.entries) other[key] = value;
  const Json doc = {{"traceEvents", events}, {"displayTimeUnit", "ms"}, {"otherData", other}};
  out << jsonText(doc) << "\n";
}

}  // namespace pbr
