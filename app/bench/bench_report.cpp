#include "app/bench/bench_report.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <string>
#include <utility>

#include <nlohmann/json.hpp>

#include "app/bench/round_ratios.hpp"
#include "app/bench/text_table.hpp"
#include "core/scene/json_text.hpp"

namespace pbr {

namespace {

// The lighting pass's median over the pairs it evaluated (PairCounts::evaluated, counted in the stats frame), in ns:
// the cost per pair a scene pays, fixed per-pixel work included; negative without a lighting pass or pairs.
double lightingNsPerPair(const BenchResult& r) {
  const PassSummary* lighting = r.pass("lighting");
  if (!lighting || r.stats.pairs.evaluated == 0) return -1.0;
  return lighting->ms.median * 1e6 / double(r.stats.pairs.evaluated);
}

// A measured value, or "-" where there is none.
std::string orDash(double value, int decimals) { return value < 0.0 ? "-" : fixedDecimals(value, decimals); }

using Json = nlohmann::ordered_json;
using Record = std::vector<std::pair<std::string, std::string>>;

const std::string kSkipped = "skipped";
const std::string kNotApplicable = "n/a";

std::string csvField(const std::string& s) {
  if (s.find_first_of(",\"\r\n") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

const char* const kStatNames[] = {"median", "p10", "p90", "min", "max"};

double statValue(const TimeSummary& t, int i) {
  const double values[] = {t.median, t.p10, t.p90, t.min, t.max};
  return values[i];
}

void addTimes(Record& record, const std::string& prefix, const TimeSummary* times, const std::string& missing) {
  for (int i = 0; i < 5; ++i) {
    record.emplace_back(prefix + "_" + kStatNames[i] + "_ms", times ? fixedDecimals(statValue(*times, i), 4) : missing);
  }
}

template <typename Enum>
std::string joined(const std::vector<Enum>& items) {
  std::string out;
  for (Enum item : items) out += (out.empty() ? "" : ",") + std::string(toString(item));
  return out;
}

std::string joinedInts(const std::vector<int>& values) {
  std::string out;
  for (int v : values) out += (out.empty() ? "" : ",") + std::to_string(v);
  return out;
}

Record settingsRecord(const BenchReport& report) {
  const BenchSettings& s = report.settings;
  const std::string density =
      "yes (light radii x sqrt(" + std::to_string(densityReferenceLights(s)) + "/lights))";
  Record record = {{"scene", s.scene},
                   {"size", std::to_string(s.size.x) + "x" + std::to_string(s.size.y)},
                   {"lights", joinedInts(s.lights)},
                   {"culling", joined(s.culling)},
                   {"models", joined(s.models)},
                   {"warmup_frames", std::to_string(s.warmup)},
                   {"timed_frames", std::to_string(s.frames)},
                   {"max_seconds", fixedDecimals(s.maxSeconds, 3)},
                   {"constant_density", s.constantDensity ? density : "no"},
                   {"spot_share", s.spotShare ? fixedDecimals(*s.spotShare, 3) : "the scene's"},
                   {"shadows", toString(s.shadows.mode)},
                   {"shadow_filter", toString(s.shadows.filter)},
                   {"shadow_atlas", std::to_string(s.shadows.atlasSize)},
                   {"shadow_cache", s.shadows.cache ? "on" : "off"},
                   {"tone_curve", toString(s.toneCurve)},
                   {"timing_requested", s.timing},
                   {"sweep_configurations", std::to_string(sweepConfigs(s).size())},
                   {"sweep_fingerprint", sweepFingerprint(s)}};
  if (report.shard) record.emplace_back("shard", report.shard->text());
  return record;
}

Json settingsJson(const BenchSettings& s) {
  Json settings = {{"scene", s.scene},
                   {"width", s.size.x},
                   {"height", s.size.y},
                   {"lights", s.lights},
                   {"culling", Json::array()},
                   {"models", Json::array()},
                   {"warmup_frames", s.warmup},
                   {"timed_frames", s.frames},
                   {"max_seconds", s.maxSeconds},
                   {"constant_density", s.constantDensity},
                   {"density_reference_lights", densityReferenceLights(s)},
                   {"spot_share", s.spotShare ? Json(*s.spotShare) : Json()},
                   {"shadows", toString(s.shadows.mode)},
                   {"shadow_filter", toString(s.shadows.filter)},
                   {"shadow_atlas", s.shadows.atlasSize},
                   {"shadow_cache", s.shadows.cache},
                   {"tone_curve", toString(s.toneCurve)},
                   {"timing_requested", s.timing}};
  for (Culling c : s.culling) settings["culling"].push_back(toString(c));
  for (ShadingModel m : s.models) settings["models"].push_back(toString(m));
  return settings;
}

// One CSV row; the column names are the same for every result, skipped or not.
Record csvRecord(const BenchResult& r, const std::vector<std::string>& passes) {
  const bool ok = !r.skipped;
  const bool clustered = r.stats.culling == Culling::Clustered && r.config.culling != Culling::None;
  Record rec = {{"scene", r.config.scene},
                {"width", std::to_string(r.config.size.x)},
                {"height", std::to_string(r.config.size.y)},
                {"lights", std::to_string(r.config.lights)},
                {"culling", toString(r.config.culling)},
                {"model", toString(r.config.model)},
                {"light_radius_scale", fixedDecimals(r.config.radiusScale, 4)},
                {"status", ok ? "ok" : kSkipped},
                {"skip_reason", ok ? "none" : r.skipReason},
                {"estimated_s", fixedDecimals(r.estimatedSeconds, 3)},
                {"elapsed_s", fixedDecimals(r.elapsedSeconds, 3)},
                {"timed_frames", std::to_string(r.frames.size())}};
  for (const std::string& name : passes) {
    const PassSummary* p = r.pass(name);
    addTimes(rec, name, p ? &p->ms : nullptr, ok ? kNotApplicable : kSkipped);
  }
  addTimes(rec, "frame", ok ? &r.frameTime : nullptr, kSkipped);
  addTimes(rec, "cpu_frame", ok ? &r.cpuTime : nullptr, kSkipped);

  const LightStats& s = r.stats;
  const auto cluster = [&](const std::string& v) { return !ok ? kSkipped : clustered ? v : kNotApplicable; };
  const auto measured = [&](const std::string& v) { return ok ? v : kSkipped; };
  const Record stats = {
      {"surviving_lights", cluster(std::to_string(s.visibleLights))},
      {"clusters", cluster(std::to_string(s.clusters))},
      {"tile_size", cluster(std::to_string(s.tileSize))},
      {"active_clusters", cluster(std::to_string(s.activeClusters))},
      {"non_empty_clusters", cluster(std::to_string(s.nonEmptyClusters))},
      {"avg_lights_per_cluster", cluster(fixedDecimals(s.averagePerNonEmpty(), 3))},
      {"max_lights_per_cluster", cluster(std::to_string(s.maxPerCluster))},
      {"index_entries", cluster(std::to_string(s.indexEntries))},
      {"overflowed_clusters", cluster(std::to_string(s.overflowedClusters))},
      {"shadowed_lights", measured(std::to_string(s.shadows.shadowedLights))},
      {"shadow_views_rendered", measured(std::to_string(s.shadows.viewsRendered))},
      {"shadow_views_skipped", measured(std::to_string(s.shadows.viewsSkipped))},
      {"pairs_evaluated", measured(std::to_string(s.pairs.evaluated))},
      {"pairs_contributing", measured(std::to_string(s.pairs.contributing))},
      {"culling_efficiency", measured(fixedDecimals(s.cullingEfficiency(), 5))},
      {"lighting_ns_per_pair", measured(orDash(lightingNsPerPair(r), 6))},
      {"gbuffer_bytes", measured(std::to_string(r.memory.gbuffer))},
      {"cluster_bytes", measured(std::to_string(r.memory.clusters))},
      {"light_bytes", measured(std::to_string(r.memory.lights))},
      {"gpu_bytes", measured(std::to_string(r.memory.total()))},
      {"process_cpu_share", measured(fixedDecimals(r.processCpuShare, 3))}};
  rec.insert(rec.end(), stats.begin(), stats.end());
  return rec;
}

Json timesJson(const TimeSummary& t) {
  Json j = Json::object();
  for (int i = 0; i < 5; ++i) j[std::string(kStatNames[i]) + "_ms"] = statValue(t, i);
  return j;
}

Json configJson(const BenchResult& r, const std::vector<std::string>& passes) {
  const bool ok = !r.skipped;
  const bool clustered = r.stats.culling == Culling::Clustered && r.config.culling != Culling::None;
  Json j = Json::object();
  j["label"] = r.config.label();
  j["scene"] = r.config.scene;
  j["width"] = r.config.size.x;
  j["height"] = r.config.size.y;
  j["lights"] = r.config.lights;
  j["culling"] = toString(r.config.culling);
  if (ok && r.stats.decision) {
    const CullingDecision& d = *r.stats.decision;
    const auto known = [](double ms) { return ms < 0.0 ? Json(nullptr) : Json(ms); };
    j["culling_auto"] = {{"ran", toString(d.ran)},
                         {"predicted_clustered_ms", known(d.clusteredMs)},
                         {"predicted_brute_force_ms", known(d.bruteForceMs)},
                         {"brute_force_at_least_ms", known(d.bruteForceAtLeastMs)},
                         {"brute_force_trial_up_to_ms", known(d.bruteForceTrialUpToMs)}};
  }
  j["model"] = toString(r.config.model);
  j["light_radius_scale"] = r.config.radiusScale;
  j["status"] = ok ? "ok" : kSkipped;
  j["skip_reason"] = ok ? Json(nullptr) : Json(r.skipReason);
  j["estimated_seconds"] = r.estimatedSeconds;
  j["elapsed_seconds"] = r.elapsedSeconds;
  j["timed_frames"] = r.frames.size();
  j["timeline_start_ms"] = r.timelineStartMs;

  Json passTimes = Json::object();
  for (const std::string& name : passes) {
    const PassSummary* p = r.pass(name);
    passTimes[name] = p ? timesJson(p->ms) : Json(nullptr);
  }
  j["passes"] = ok ? passTimes : Json(nullptr);
  j["frame"] = ok ? timesJson(r.frameTime) : Json(nullptr);
  j["cpu_frame"] = ok ? timesJson(r.cpuTime) : Json(nullptr);

  Json frames = Json::array();
  for (const FrameTiming& f : r.frames) {
    Json frame = {{"frame", f.frame}, {"start_ms", f.startMs - r.frames.front().startMs}, {"gpu_ms", f.gpuMs},
                  {"cpu_ms", f.cpuMs}};
    Json ms = Json::object(), starts = Json::object();
    for (const PassTiming& p : f.passes) {
      ms[p.name] = p.ms;
      starts[p.name] = p.startMs;
    }
    frame["passes_ms"] = ms;
    frame["passes_start_ms"] = starts;
    frames.push_back(frame);
  }
  j["frames"] = frames;

  const LightStats& s = r.stats;
  const auto cluster = [&](const Json& v) { return clustered ? v : Json(nullptr); };
  j["light_stats"] = ok ? Json{{"lights", s.lights},
                               {"surviving_lights", cluster(s.visibleLights)},
                               {"clusters", cluster(s.clusters)},
                               {"tile_size", cluster(s.tileSize)},
                               {"active_clusters", cluster(s.activeClusters)},
                               {"non_empty_clusters", cluster(s.nonEmptyClusters)},
                               {"avg_lights_per_cluster", cluster(s.averagePerNonEmpty())},
                               {"max_lights_per_cluster", cluster(s.maxPerCluster)},
                               {"index_entries", cluster(s.indexEntries)},
                               {"overflowed_clusters", cluster(s.overflowedClusters)},
                               {"shadowed_lights", s.shadows.shadowedLights},
                               {"shadow_views_rendered", s.shadows.viewsRendered},
                               {"shadow_views_skipped", s.shadows.viewsSkipped},
                               {"pairs_evaluated", s.pairs.evaluated},
                               {"pairs_contributing", s.pairs.contributing},
                               {"culling_efficiency", s.cullingEfficiency()},
                               {"lighting_ns_per_pair", lightingNsPerPair(r) < 0.0 ? Json(nullptr)
                                                                                   : Json(lightingNsPerPair(r))}}
                        : Json(nullptr);
  j["memory_bytes"] = ok ? Json{{"gbuffer", r.memory.gbuffer},
                                {"clusters", r.memory.clusters},
                                {"lights", r.memory.lights},
                                {"total", r.memory.total()}}
                         : Json(nullptr);
  j["process_cpu_share"] = ok ? Json(r.processCpuShare) : Json(nullptr);
  return j;
}

}  // namespace

std::string sweepFingerprint(const BenchSettings& settings) {
  std::uint64_t hash = 14695981039346656037ull;
  for (unsigned char c : jsonText(settingsJson(settings))) {
    hash ^= c;
    hash *= 1099511628211ull;
  }
  char text[17];
  std::snprintf(text, sizeof(text), "%016llx", static_cast<unsigned long long>(hash));
  return text;
}

KeyValues benchCsvProvenance(const BenchReport& report) {
  KeyValues entries = report.provenance.entries;
  for (const auto& entry : settingsRecord(report)) entries.push_back(entry);
  return entries;
}

void writeBenchCsv(std::ostream& out, const BenchReport& report) {
  const std::vector<std::string> passes = reportedPasses(report.results);
  const Record header = csvRecord(BenchResult{}, passes);
  for (size_t i = 0; i < header.size(); ++i) out << (i ? "," : "") << header[i].first;
  out << "\n";
  for (const BenchResult& r : report.results) {
    const Record rec = csvRecord(r, passes);
    for (size_t i = 0; i < rec.size(); ++i) out << (i ? "," : "") << csvField(rec[i].second);
    out << "\n";
  }
}

void writeBenchJson(std::ostream& out, const BenchReport& report) {
  Json provenance = Json::object();
  for (const auto& [key, value] : report.provenance.entries) provenance[key] = value;
  const std::vector<std::string> passes = reportedPasses(report.results);
  Json configurations = Json::array();
  for (const BenchResult& r : report.results) configurations.push_back(configJson(r, passes));
  Json doc = {{"schema", "pbr-bench/1"},
              {"provenance", provenance},
              {"settings", settingsJson(report.settings)},
              {"sweep",
               {{"configurations", sweepConfigs(report.settings).size()},
                {"fingerprint", sweepFingerprint(report.settings)}}}};
  if (report.shard) doc["shard"] = {{"index", report.shard->index}, {"count", report.shard->count}};
  if (!report.renderSettings.empty()) {
    Json settings = Json::object();
    for (const auto& [option, value] : report.renderSettings) settings[option] = value;
    doc["render_settings"] = settings;
  }
  doc["configurations"] = configurations;
  out << jsonText(doc, 2) << "\n";
}

void printBenchTable(std::ostream& out, const BenchReport& report) {
  const BenchSettings& s = report.settings;
  const std::vector<std::string> passes = reportedPasses(report.results);
  std::vector<std::string> header = {"lights", "culling", "model"};
  header.insert(header.end(), passes.begin(), passes.end());
  for (const char* h :
       {"frame", "p10-p90", "cpu", "lights/cluster", "efficiency", "ns/pair", "GPU MiB", "CPU use"}) {
    header.push_back(h);
  }

  std::vector<std::vector<std::string>> rows = {header};
  for (const BenchResult& r : report.results) {
    std::string culling = toString(r.config.culling);
    if (r.config.culling == Culling::Auto && !r.skipped) culling += std::string("->") + toString(r.stats.culling);
    std::vector<std::string> row = {std::to_string(r.config.lights), culling, toString(r.config.model)};
    if (!r.skipped) {
      for (const std::string& name : passes) {
        const PassSummary* p = r.pass(name);
        row.push_back(p ? fixedDecimals(p->ms.median, 2) : "-");
      }
      const bool clustered = r.stats.culling == Culling::Clustered && r.config.culling != Culling::None;
      row.push_back(fixedDecimals(r.frameTime.median, 2));
      row.push_back(fixedDecimals(r.frameTime.p10, 1) + "-" + fixedDecimals(r.frameTime.p90, 1));
      row.push_back(fixedDecimals(r.cpuTime.median, 2));
      row.push_back(clustered ? fixedDecimals(r.stats.averagePerNonEmpty(), 1) + " (max " +
                                    std::to_string(r.stats.maxPerCluster) + ")"
                              : "-");
      row.push_back(fixedDecimals(r.stats.cullingEfficiency(), 3));
      row.push_back(orDash(lightingNsPerPair(r), lightingNsPerPair(r) < 0.1 ? 4 : 2));
      row.push_back(fixedDecimals(static_cast<double>(r.memory.total()) / (1 << 20), 1));
      row.push_back(fixedDecimals(r.processCpuShare * 100.0, 0) + "%");
    }
    rows.push_back(row);
  }
  const TextTable table(std::move(rows), {1, 2});

  out << s.scene << " " << s.size.x << "x" << s.size.y << ": median ms of " << s.frames << " timed frames after "
      << s.warmup << " warm-up" << (report.provenance.get("frame_order").empty() ? "" : ", configurations in turn")
      << ", " << report.provenance.get("timing_mode") << "\n"
      << report.provenance.get("gl_renderer") << ": " << report.provenance.get("timing_note") << "\n\n";
  out << table.line(0) << "\n";
  for (size_t i = 0; i < report.results.size(); ++i) {
    out << table.line(i + 1);
    if (report.results[i].skipped) out << "  skipped: " << report.results[i].skipReason;
    out << "\n";
  }
  printRoundRatios(out, report);
}

}  // namespace pbr
