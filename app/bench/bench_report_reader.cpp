#include "app/bench/bench_report_reader.hpp"

#include <cstdint>
#include <limits>
#include <stdexcept>

#include "core/scene/json_field.hpp"
#include "core/scene/json_file.hpp"

namespace pbr {

namespace {

constexpr const char* kSchema = "pbr-bench/1";
constexpr uint64_t kMaxCount = std::numeric_limits<uint32_t>::max();
constexpr uint64_t kMaxLights = 1 << 20;  // as pbr bench --lights accepts
constexpr uint64_t kMaxSide = 16384;      // as --size accepts
constexpr uint64_t kMaxFrames = 100000;   // as --warmup and --frames accept

template <typename T>
T keyword(const JsonField& field, T (*parse)(const std::string&)) {
  const std::string name = field.string();
  try {
    return parse(name);
  } catch (const std::invalid_argument& e) {
    field.fail(e.what());
  }
}

int integer(const JsonField& field, uint64_t max) { return static_cast<int>(field.integer(max)); }

// A null count is one the report marks not applicable (cluster statistics of brute-force frames).
uint64_t countOrZero(const JsonField& field, uint64_t max = kMaxCount) {
  return field.isNull() ? 0 : field.integer(max);
}

BenchSettings readSettings(const JsonField& f) {
  BenchSettings s;
  s.scene = f["scene"].string();
  s.size = {integer(f["width"], kMaxSide), integer(f["height"], kMaxSide)};
  s.lights.clear();
  for (const JsonField& l : f["lights"].items()) s.lights.push_back(integer(l, kMaxLights));
  s.culling.clear();
  for (const JsonField& c : f["culling"].items()) s.culling.push_back(keyword(c, parseCulling));
  s.models.clear();
  for (const JsonField& m : f["models"].items()) s.models.push_back(keyword(m, parseShadingModel));
  s.warmup = integer(f["warmup_frames"], kMaxFrames);
  s.frames = integer(f["timed_frames"], kMaxFrames);
  s.maxSeconds = f["max_seconds"].real(NumberRule::atLeast(0.0));
  const JsonField density = f["constant_density"];
  if (!density.present()) density.expected("true or false");
  s.constantDensity = density.boolean(false);
  const JsonField spotShare = f["spot_share"];
  if (!spotShare.isNull()) s.spotShare = static_cast<float>(spotShare.real(NumberRule::closed(0.0, 1.0)));
  s.shadows.mode = keyword(f["shadows"], parseShadowMode);
  s.shadows.filter = keyword(f["shadow_filter"], parseShadowFilter);
  s.shadows.atlasSize = integer(f["shadow_atlas"], kMaxShadowAtlas);
  // Reports from before --shadow-cache drew the maps every frame.
  s.shadows.cache = f["shadow_cache"].boolean(false);
  // Reports from before --tonemap ran ACES Hill.
  if (f["tone_curve"].present()) s.toneCurve = keyword(f["tone_curve"], parseToneCurve);
  s.timing = f["timing_requested"].string();
  return s;
}

// Pass start offsets are optional: reports written before they were recorded lack them (`layout` turns false).
FrameTiming readFrame(const JsonField& f, bool& layout) {
  FrameTiming frame;
  frame.frame = integer(f["frame"], static_cast<uint64_t>(std::numeric_limits<int>::max()));
  frame.startMs = f["start_ms"].real(NumberRule::any());
  frame.gpuMs = f["gpu_ms"].real(NumberRule::atLeast(0.0));
  frame.cpuMs = f["cpu_ms"].real(NumberRule::atLeast(0.0));
  for (const auto& [name, ms] : f["passes_ms"].members()) {
    frame.passes.push_back({name, ms.real(NumberRule::atLeast(0.0)), 0.0});
  }
  const JsonField starts = f["passes_start_ms"];
  if (!starts.present()) {
    layout = false;
    return frame;
  }
  for (PassTiming& p : frame.passes) p.startMs = starts[p.name].real(NumberRule::atLeast(0.0));
  return frame;
}

BenchResult readResult(const JsonField& c, bool& layout) {
  BenchResult r;
  r.config.scene = c["scene"].string();
  r.config.size = {integer(c["width"], kMaxSide), integer(c["height"], kMaxSide)};
  r.config.lights = integer(c["lights"], kMaxLights);
  r.config.culling = keyword(c["culling"], parseCulling);
  r.config.model = keyword(c["model"], parseShadingModel);
  r.config.radiusScale = static_cast<float>(c["light_radius_scale"].real(NumberRule::atLeast(0.0)));
  const JsonField status = c["status"];
  if (status.string() != "ok" && status.string() != "skipped") status.expected("\"ok\" or \"skipped\"");
  r.skipped = status.string() == "skipped";
  if (r.skipped) r.skipReason = c["skip_reason"].string();
  r.estimatedSeconds = c["estimated_seconds"].real(NumberRule::atLeast(0.0));
  r.elapsedSeconds = c["elapsed_seconds"].real(NumberRule::atLeast(0.0));
  const JsonField timeline = c["timeline_start_ms"];
  if (timeline.present()) {
    r.timelineStartMs = timeline.real(NumberRule::atLeast(0.0));
  } else {
    layout = false;
  }
  for (const JsonField& f : c["frames"].items()) r.frames.push_back(readFrame(f, layout));
  r.summarize();
  if (r.skipped) return r;

  const JsonField s = c["light_stats"];
  r.stats.lights = static_cast<uint32_t>(s["lights"].integer(kMaxCount));
  r.stats.visibleLights = static_cast<uint32_t>(countOrZero(s["surviving_lights"]));
  r.stats.clusters = static_cast<uint32_t>(countOrZero(s["clusters"]));
  r.stats.activeClusters = static_cast<uint32_t>(countOrZero(s["active_clusters"]));
  r.stats.nonEmptyClusters = static_cast<uint32_t>(countOrZero(s["non_empty_clusters"]));
  r.stats.maxPerCluster = static_cast<uint32_t>(countOrZero(s["max_lights_per_cluster"]));
  r.stats.indexEntries = countOrZero(s["index_entries"], std::numeric_limits<uint64_t>::max());
  r.stats.overflowedClusters = static_cast<uint32_t>(countOrZero(s["overflowed_clusters"]));
  r.stats.shadows.shadowedLights = static_cast<uint32_t>(s["shadowed_lights"].integer(kMaxCount));
  r.stats.shadows.viewsRendered = static_cast<uint32_t>(s["shadow_views_rendered"].integer(kMaxCount));
  r.stats.shadows.viewsSkipped = static_cast<uint32_t>(s["shadow_views_skipped"].integer(kMaxCount));
  r.stats.pairs.evaluated = s["pairs_evaluated"].integer(std::numeric_limits<uint64_t>::max());
  r.stats.pairs.contributing = s["pairs_contributing"].integer(std::numeric_limits<uint64_t>::max());
  const JsonField memory = c["memory_bytes"];
  const uint64_t maxBytes = std::numeric_limits<size_t>::max();
  r.memory = {memory["gbuffer"].integer(maxBytes), memory["clusters"].integer(maxBytes),
              memory["lights"].integer(maxBytes)};
  r.processCpuShare = c["process_cpu_share"].real(NumberRule::atLeast(0.0));
  return r;
}

}  // namespace

BenchReportFile readBenchReport(const std::string& path) {
  const nlohmann::json doc = readJsonFile(path);
  const JsonField root(doc, path);
  const JsonField schema = root["schema"];
  if (!schema.isString() || schema.string() != kSchema) {
    schema.expected("\"" + std::string(kSchema) + "\" (a report of pbr bench --json)");
  }
  BenchReportFile file;
  const JsonField provenance = root["provenance"];
  if (!provenance.present()) provenance.expected("an object");
  for (const auto& [key, value] : provenance.members()) file.report.provenance.set(key, value.string());
  file.report.settings = readSettings(root["settings"]);
  file.settings = doc.at("settings");
  file.sweepFingerprint = root["sweep"]["fingerprint"].string();
  const JsonField shard = root["shard"];
  if (shard.present()) {
    const int count = integer(shard["count"], kMaxShards);
    const int index = integer(shard["index"], static_cast<uint64_t>(count));
    if (count < 1 || index < 1) shard.expected("an index K and a count N with 1 <= K <= N");
    file.report.shard = BenchShard{index, count};
  }
  const JsonField configurations = root["configurations"];
  if (!configurations.present()) configurations.expected("an array");
  for (const JsonField& c : configurations.items()) {
    file.report.results.push_back(readResult(c, file.traceLayout));
    file.report.results.back().config.shadows = file.report.settings.shadows;  // every configuration's, as measured
    file.report.results.back().config.toneCurve = file.report.settings.toneCurve;
  }
  return file;
}

}  // namespace pbr
