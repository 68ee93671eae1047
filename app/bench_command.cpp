#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <memory>
#include <numeric>
#include <optional>
#include <sstream>

#include "app/accuracy/accuracy_variants.hpp"
#include "app/accuracy/pair_cost.hpp"
#include "app/accuracy/pair_cost_report.hpp"
#include "app/args.hpp"
#include "app/bench/bench_progress.hpp"
#include "app/bench/bench_report.hpp"
#include "app/bench/bench_run.hpp"
#include "app/bench/bench_shard.hpp"
#include "app/bench/trace_writer.hpp"
#include "app/commands.hpp"
#include "app/option_table.hpp"
#include "app/common_options.hpp"
#include "app/file_clash.hpp"
#include "app/scene_source.hpp"
#include "core/gl/context.hpp"
#include "core/io/output_file.hpp"

namespace pbr {

namespace {

std::vector<std::string> splitList(const std::string& option, const std::string& text) {
  std::vector<std::string> items;
  for (size_t start = 0;;) {
    const size_t comma = text.find(',', start);
    const std::string item = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    if (item.empty()) {
      throw UsageError(option + " expects a comma-separated list without empty items, got '" + text + "'");
    }
    for (const std::string& seen : items) {
      if (seen == item) throw UsageError(option + " lists '" + item + "' twice");
    }
    items.push_back(item);
    if (comma == std::string::npos) return items;
    start = comma + 1;
  }
}

std::vector<int> parseLightCounts(const std::string& text) {
  constexpr long kMax = 1 << 20;
  std::vector<int> counts;
  for (const std::string& item : splitList("--lights", text)) {
    char* end = nullptr;
    errno = 0;
    const long v = std::strtol(item.c_str(), &end, 10);
    if (*end != '\0' || errno == ERANGE || v < 0 || v > kMax) {
      throw UsageError("--lights expects comma-separated light counts in [0, " + std::to_string(kMax) + "], got '" +
                       text + "'");
    }
    counts.push_back(static_cast<int>(v));
  }
  return counts;
}

template <typename T>
std::vector<T> parseEach(const std::string& option, const std::string& text, T (*parse)(const std::string&)) {
  std::vector<T> values;
  for (const std::string& item : splitList(option, text)) values.push_back(parse(item));
  return values;
}

BenchSettings parseSettings(const Args& args) {
  BenchSettings s;
  s.scene = args.get("--scene");
  s.lights = parseLightCounts(args.get("--lights"));
  s.culling = parseEach("--culling", args.get("--culling"), parseCulling);
  s.models = parseEach("--model", args.get("--model"), parseShadingModel);
  s.size = args.getSize("--size");
  s.warmup = args.getInt("--warmup", 1, 100000);
  s.frames = args.getInt("--frames", 1, 100000);
  s.maxSeconds = args.getFloat("--max-seconds", 0.0f, 1e7f);
  s.constantDensity = args.has("--constant-density");
  s.spotShare = sceneFileParams(args).spotShare;
  s.shadows = readShadowSettings(args);
  s.toneCurve = readToneCurve(args);
  s.timing = args.get("--timing");
  chooseTimingMode(s.timing, "");  // rejects a bad mode before a context is made
  return s;
}

// Output files are opened before the sweep, so that a bad path or name fails at once rather than after an hour;
// each is renamed into place only once all of it is written.
std::unique_ptr<OutputFile> openOutput(const Args& args, const std::string& option) {
  if (!args.has(option)) return nullptr;
  requireExtension(args.get(option), option == "--csv" ? ".csv" : ".json");
  return std::make_unique<OutputFile>(args.get(option));
}

void finishOutput(OutputFile* out, const std::function<void(std::ostream&)>& body) {
  if (!out) return;
  out->write(body);
  std::printf("wrote %s\n", out->path().c_str());
}

// The provenance file beside --csv's (csv_provenance.hpp), opened with it.
std::unique_ptr<OutputFile> openCsvProvenance(const Args& args) {
  return args.has("--csv") ? std::make_unique<OutputFile>(provenancePath(args.get("--csv"))) : nullptr;
}

PairCostSettings parsePairCostSettings(const Args& args) {
  PairCostSettings s;
  s.size = args.getSize("--size");
  s.lights = args.getInt("--pair-lights", 1, 1 << 16);
  s.rounds = args.getInt("--rounds", 1, 10000);
  if (args.has("--pair-scene")) s.scene = args.get("--pair-scene");
  return s;
}

int runPairCost(const Args& args, PairCostSettings settings, const EglPlatform platform) {
  PairCostReport report;
  std::vector<FixtureMaterial> materials;
  std::stringstream list(args.get("--pair-materials"));
  for (std::string item; std::getline(list, item, ',');) materials.push_back(parseFixtureMaterial(item));
  std::optional<Scene> scene;
  if (!settings.scene.empty()) {
    if (args.has("--pair-materials")) throw UsageError("--pair-materials belongs to the fixture, not --pair-scene");
    SceneParams params = sceneFileParams(args);
    params.defaultEnvironment = DefaultEnvironment::None;  // as the sweep: the lights' pairs, not the sky's
    params.lights = settings.lights;
    scene = resolveScene(settings.scene, params);
  }
  // Each variant on each material, the materials innermost: a lobe's cost reads beside its variant's core row; on
  // a scene each variant brute force, then clustered.
  const std::vector<Culling> cullings =
      scene ? std::vector<Culling>{Culling::None, Culling::Clustered} : std::vector<Culling>{Culling::None};
  std::vector<PairCostVariant> variants;
  for (const AccuracyVariant& v : selectVariants(args.get("--pair-cost"))) {
    for (const FixtureMaterial material : materials) {
      for (const Culling culling : cullings) {
        report.variants.push_back(v);
        variants.push_back(pairCostVariant(v));
        variants.back().material = material;
        variants.back().culling = culling;
      }
    }
  }
  report.settings = settings;
  const std::unique_ptr<OutputFile> csv = openOutput(args, "--csv");
  const std::unique_ptr<OutputFile> csvProvenance = openCsvProvenance(args);
  const std::unique_ptr<OutputFile> json = openOutput(args, "--json");
  const std::string timingRequest = args.get("--timing");
  auto context = createHeadlessContext(platform);
  report.settings.timing = chooseTimingMode(timingRequest, context->info().renderer);
  report.provenance = collectProvenance(context->info(), report.settings.timing);
  const ShaderLibrary shaders;
  const bool terminal = ::isatty(STDERR_FILENO) == 1;
  report.costs = measurePairCost(shaders, variants, report.settings, scene ? &*scene : nullptr, [&](int done, int total) {
    if (terminal) std::fprintf(stderr, "\rpair cost: %d/%d frames timed", done, total);
    if (terminal && done == total) std::fprintf(stderr, "\n");
  });
  checkGlError("measuring the cost per light-pixel pair");
  report.provenance.set("load_average_end", loadAverage());
  printPairCostTable(std::cout, report);
  finishOutput(csv.get(), [&](std::ostream& out) { writePairCostCsv(out, report); });
  finishOutput(csvProvenance.get(), [&](std::ostream& out) { writeKeyValues(out, pairCostCsvProvenance(report)); });
  finishOutput(json.get(), [&](std::ostream& out) { writePairCostJson(out, report); });
  return 0;
}

// The sweep's configurations this run measures: all of them, or its --shard's share.
std::vector<BenchConfig> shardConfigs(const std::vector<BenchConfig>& sweep, const std::optional<BenchShard>& shard) {
  if (shard && static_cast<size_t>(shard->count) > sweep.size()) {
    throw UsageError("--shard " + shard->text() + ": the sweep has " + std::to_string(sweep.size()) +
                     " configurations, too few for " + std::to_string(shard->count) + " shards");
  }
  std::vector<size_t> positions(sweep.size());
  std::iota(positions.begin(), positions.end(), size_t{0});
  if (shard) positions = shardPositions(sweep, *shard);
  std::vector<BenchConfig> configs;
  for (size_t p : positions) configs.push_back(sweep[p]);
  return configs;
}

// A scene per light count, every one before any rendering, so that a bad scene or light count fails at once.
std::vector<Scene> loadSweepScenes(const Args& args, const BenchSettings& settings) {
  std::vector<Scene> scenes;
  for (int lights : settings.lights) {
    SceneParams params = sceneFileParams(args);
    params.defaultEnvironment = DefaultEnvironment::None;  // timings stay comparable with earlier runs
    params.lights = lights;
    Scene scene = resolveScene(settings.scene, params);
    const float scale = settings.constantDensity ? densityRadiusScale(lights, densityReferenceLights(settings)) : 1.0f;
    for (PointLight& l : scene.lights) l.radius *= scale;
    scenes.push_back(std::move(scene));
  }
  return scenes;
}

// Every configuration keeps its renderer while the sweep takes their frames in turn, a frame each per round, so
// that the machine's drift (another tenant, clocks, heat) falls on all alike; the results in `configs`' order.
std::vector<BenchResult> measureInTurn(const std::vector<BenchConfig>& configs, const std::vector<Scene>& scenes,
                                       const BenchSettings& settings, TimingMode timing) {
  const ShaderLibrary shaders;
  BenchProgress progress(configs, settings, ::isatty(STDERR_FILENO) == 1);
  const BenchClock::time_point sweepStart = BenchClock::now();
  std::vector<std::unique_ptr<BenchRun>> runs;
  for (size_t index = 0; index < configs.size(); ++index) {
    const BenchConfig& config = configs[index];
    const size_t li = static_cast<size_t>(
        std::find(settings.lights.begin(), settings.lights.end(), config.lights) - settings.lights.begin());
    runs.push_back(std::make_unique<BenchRun>(shaders, scenes[li], config, timing));
    runs.back()->probe(settings);
    progress.rendered(index, runs.back()->frameSeconds());
    progress.probed(index, runs.back()->partial());
  }
  const auto inTurn = [&](const char* phase, int rounds, const std::function<void(BenchRun&)>& frame) {
    for (int round = 1; round <= rounds; ++round) {
      progress.round(phase, round, rounds);
      for (size_t index = 0; index < runs.size(); ++index) {
        if (runs[index]->skipped()) continue;
        frame(*runs[index]);
        progress.rendered(index, runs[index]->frameSeconds());
      }
    }
  };
  inTurn("warm-up", settings.warmup - 1, [](BenchRun& run) { run.warmUpFrame(); });
  inTurn("timed", settings.frames, [&](BenchRun& run) {
    run.timedFrame(std::chrono::duration<double, std::milli>(BenchClock::now() - sweepStart).count());
  });
  std::vector<BenchResult> results;
  for (size_t index = 0; index < runs.size(); ++index) {
    const double frameSeconds = runs[index]->frameSeconds();
    BenchResult result = runs[index]->finish();
    runs[index].reset();
    if (!result.skipped) progress.rendered(index, frameSeconds);
    progress.finished(index, result);
    results.push_back(std::move(result));
  }
  return results;
}

}  // namespace

int runBench(const std::vector<std::string>& argv) {
  const auto& specs = commandOptions(Command::Bench);
  const Args args(specs, argv);
  if (args.helpRequested()) {
    std::cout << Args::helpText("pbr bench [options]",
                                "Measures per-pass frame times for every combination of light count, culling mode "
                                "and shading model, with light statistics and GPU memory, and writes them as a "
                                "table, CSV, JSON and a Chrome trace, each with the circumstances of the run.",
                                specs);
    return 0;
  }
  const EglPlatform platform = parseEglPlatform(args.get("--egl-platform"));
  std::vector<NamedFile> inputs;
  if (!isBuiltinScene(args.get("--scene"))) inputs.push_back({"--scene", args.get("--scene")});
  checkOutputsApart(inputs, {{"--csv", args.get("--csv")},
                             {"--csv's provenance", args.has("--csv") ? provenancePath(args.get("--csv")) : ""},
                             {"--json", args.get("--json")}, {"--trace", args.get("--trace")}});
  if (args.has("--pair-cost")) {
    for (const char* sweepOnly : {"--trace", "--lights", "--culling", "--model", "--constant-density", "--shard"}) {
      if (args.has(sweepOnly)) throw UsageError(std::string(sweepOnly) + " belongs to the sweep, not --pair-cost");
    }
    chooseTimingMode(args.get("--timing"), "");
    return runPairCost(args, parsePairCostSettings(args), platform);
  }
  for (const char* pairOnly : {"--pair-lights", "--rounds", "--pair-materials"}) {
    if (args.has(pairOnly)) throw UsageError(std::string(pairOnly) + " belongs to --pair-cost");
  }
  const BenchSettings settings = parseSettings(args);
  const std::vector<BenchConfig> sweep = sweepConfigs(settings);
  const std::optional<BenchShard> shard = args.has("--shard") ? std::optional(parseShard(args.get("--shard")))
                                                               : std::nullopt;
  const std::vector<BenchConfig> configs = shardConfigs(sweep, shard);
  const std::vector<Scene> scenes = loadSweepScenes(args, settings);
  const std::unique_ptr<OutputFile> csv = openOutput(args, "--csv");
  const std::unique_ptr<OutputFile> csvProvenance = openCsvProvenance(args);
  const std::unique_ptr<OutputFile> json = openOutput(args, "--json");
  const std::unique_ptr<OutputFile> trace = openOutput(args, "--trace");

  auto context = createHeadlessContext(platform);
  const TimingMode timing = chooseTimingMode(settings.timing, context->info().renderer);
  BenchReport report;
  report.settings = settings;
  report.shard = shard;
  report.provenance = collectProvenance(context->info(), timing);
  report.provenance.set("frame_order", "each configuration's first frame, then theirs in turn, a frame each per round");
  const std::string part =
      shard ? " (shard " + shard->text() + " of " + std::to_string(sweep.size()) + ")" : std::string();
  std::fprintf(stderr, "bench: %zu configurations%s on %s, %s\n", configs.size(), part.c_str(),
               context->info().renderer.c_str(), describe(timing));
  report.results = measureInTurn(configs, scenes, settings, timing);
  report.provenance.set("load_average_end", loadAverage());

  printBenchTable(std::cout, report);
  finishOutput(csv.get(), [&](std::ostream& out) { writeBenchCsv(out, report); });
  finishOutput(csvProvenance.get(), [&](std::ostream& out) { writeKeyValues(out, benchCsvProvenance(report)); });
  finishOutput(json.get(), [&](std::ostream& out) { writeBenchJson(out, report); });
  finishOutput(trace.get(), [&](std::ostream& out) { writeTrace(out, report); });
  return 0;
}

}  // namespace pbr
