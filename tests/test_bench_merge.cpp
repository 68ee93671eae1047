// `pbr bench-merge` on shard reports that the report writer makes from made-up measurements (no context needed):
// the merge gives back the unsharded report row for row, and every way shards can fail to make one sweep is
// refused with one line naming the file.
#include <doctest/doctest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/bench/bench_report.hpp"
#include "app/bench/bench_shard.hpp"
#include "tests/cli_util.hpp"
#include "tests/refusal_checks.hpp"

using pbr::BenchReport;
using pbr::BenchResult;
using pbr::BenchSettings;
using pbr::test::PbrRun;
using pbr::test::TempDir;
using Json = nlohmann::json;

namespace {

// 4 and 8 lights, both culling modes, PBR: four configurations, of which brute force at 8 lights was skipped.
BenchSettings tinySweep(std::vector<int> lights = {4, 8}) {
  BenchSettings s;
  s.scene = "default";
  s.size = {32, 32};
  s.lights = std::move(lights);
  s.models = {pbr::ShadingModel::Pbr};
  s.culling = {pbr::Culling::None, pbr::Culling::Clustered};
  s.warmup = 1;
  s.frames = 2;
  return s;
}

// Times that no two configurations share and whose last digits matter, so that a row put in the wrong place or a
// value rounded on the way through JSON changes the CSV.
BenchResult measured(const pbr::BenchConfig& config, size_t position) {
  BenchResult r;
  r.config = config;
  const double base = 1.0 + 0.123456789 * static_cast<double>(position + 1);
  r.estimatedSeconds = base / 7.0;
  r.elapsedSeconds = base / 3.0;
  if (config.lights == 8 && config.culling == pbr::Culling::None) {
    r.skipped = true;
    r.skipReason = "estimated 9.9 s (first warm-up frame 3.300 s x 3 frames) exceeds --max-seconds 5";
    return r;
  }
  const bool clustered = config.culling == pbr::Culling::Clustered;
  r.timelineStartMs = 1000.0 * static_cast<double>(position) + 0.25;
  for (int f = 0; f < 2; ++f) {
    pbr::FrameTiming frame;
    frame.frame = 2 + f;
    frame.startMs = 100.0 * f + base;
    double start = 0.0;
    for (const char* pass : {"gbuffer", "cluster", "lighting", "post"}) {
      if (!clustered && std::string(pass) == "cluster") continue;
      frame.passes.push_back({pass, base * (f + 1) + 0.0000123 * pass[0], start});
      start += frame.passes.back().ms + 0.001;
    }
    frame.gpuMs = 10.0 * base + f / 3.0;  // longer than its passes together, so that none is clipped in a trace
    frame.cpuMs = 5.0 * base + f / 7.0;
    r.frames.push_back(frame);
  }
  r.stats.lights = static_cast<uint32_t>(config.lights);
  r.stats.visibleLights = clustered ? 3 : 99;
  r.stats.clusters = 3456;
  r.stats.activeClusters = 321;
  r.stats.nonEmptyClusters = 123 + static_cast<uint32_t>(position);
  r.stats.maxPerCluster = 3;
  r.stats.indexEntries = 250;
  r.stats.pairs = {1000 + position, 333};
  r.memory = {4096, clustered ? 2048u : 0u, 1024};
  r.processCpuShare = 0.87654321;
  r.summarize();
  return r;
}

BenchReport report(const BenchSettings& settings, std::optional<pbr::BenchShard> shard, const std::string& command) {
  BenchReport r;
  r.settings = settings;
  r.shard = shard;
  for (const auto& [key, value] : std::vector<std::pair<std::string, std::string>>{
           {"command", command},
           {"run_date_utc", "2026-01-01T00:00:00Z"},
           {"gl_renderer", "llvmpipe (LLVM 15.0.6, 256 bits)"},
           {"gl_version", "4.5 (Core Profile) Mesa 22.3.6"},
           {"cpu_model", "Example CPU"},
           {"git_commit", "0123456789abcdef0123456789abcdef01234567"},
           {"build_type", "Release"},
           {"load_average_end", shard ? std::to_string(shard->index) + ".00 0.50 0.25" : "9.00 0.50 0.25"}}) {
    r.provenance.set(key, value);
  }
  const std::vector<pbr::BenchConfig> sweep = pbr::sweepConfigs(settings);
  std::vector<size_t> positions;
  for (size_t p = 0; p < sweep.size(); ++p) positions.push_back(p);
  if (shard) positions = pbr::shardPositions(sweep, *shard);
  for (size_t p : positions) r.results.push_back(measured(sweep[p], p));
  return r;
}

std::string writeJson(const TempDir& dir, const std::string& name, const BenchReport& r) {
  std::ostringstream out;
  pbr::writeBenchJson(out, r);
  return dir.write(name, out.str());
}

std::string csvText(const BenchReport& r) {
  std::ostringstream out;
  pbr::writeBenchCsv(out, r);
  return out.str();
}

// Shards 1 and 2 of 2 of the tiny sweep.
struct Shards {
  std::string one, two;
};
Shards writeShards(const TempDir& dir, const BenchSettings& settings = tinySweep()) {
  return {writeJson(dir, "shard-1.json", report(settings, pbr::BenchShard{1, 2}, "pbr bench --shard 1/2")),
          writeJson(dir, "shard-2.json", report(settings, pbr::BenchShard{2, 2}, "pbr bench --shard 2/2"))};
}

// A copy of `path` as `name` with `edit` applied to its JSON.
template <typename Edit>
std::string editedCopy(const TempDir& dir, const std::string& path, const std::string& name, Edit edit) {
  Json doc = Json::parse(pbr::test::readFile(path));
  edit(doc);
  return dir.write(name, doc.dump(2));
}

PbrRun merge(const TempDir& dir, std::vector<std::string> args) {
  args.insert(args.begin(), "bench-merge");
  return pbr::test::runPbr(dir, args);
}

void checkRefusedNaming(const PbrRun& run, const std::string& file, const std::string& problem) {
  CAPTURE(run.err);
  CHECK(run.exitCode == 1);
  pbr::test::checkOneLineNaming(run, file);
  CHECK(run.err.find(problem) != std::string::npos);
}

}  // namespace

TEST_CASE("bench-merge: two shards merge into the CSV and JSON of the unsharded sweep, rows in sweep order") {
  const TempDir dir;
  const BenchReport whole = report(tinySweep(), std::nullopt, "pbr bench");
  const Shards shards = writeShards(dir);
  // Given in reverse: the order of the files does not matter.
  const PbrRun run = merge(dir, {shards.two, shards.one, "--csv", dir.file("merged.csv"), "--json",
                                 dir.file("merged.json")});
  CAPTURE(run.err);
  REQUIRE(run.exitCode == 0);
  CHECK(run.out.find("skipped") != std::string::npos);  // the table

  CHECK(pbr::test::readFile(dir.file("merged.csv")) == csvText(whole));
  const std::string provenance = pbr::test::readFile(dir.file("merged.provenance.txt"));
  CHECK(provenance.find("\nsweep_fingerprint: " + pbr::sweepFingerprint(tinySweep()) + "\n") != std::string::npos);
  CHECK(provenance.find("\nshard:") == std::string::npos);
  CHECK(provenance.find("command: shard 1: pbr bench --shard 1/2; shard 2: pbr bench --shard 2/2\n") !=
        std::string::npos);
  CHECK(provenance.find("\ngl_renderer: llvmpipe (LLVM 15.0.6, 256 bits)\n") != std::string::npos);
  CHECK(provenance.find("\nmerged_shards: 2: " + shards.one + ", " + shards.two + "\n") != std::string::npos);
  // Keys in the order the bench writes them, not the JSON's sorted order.
  CHECK(provenance.find("run_date_utc:") < provenance.find("gl_renderer:"));

  std::ostringstream wholeJson;
  pbr::writeBenchJson(wholeJson, whole);
  const Json expected = Json::parse(wholeJson.str());
  const Json merged = Json::parse(pbr::test::readFile(dir.file("merged.json")));
  CHECK(merged.at("configurations") == expected.at("configurations"));
  CHECK(merged.at("settings") == expected.at("settings"));
  CHECK(merged.at("sweep") == expected.at("sweep"));
  CHECK_FALSE(merged.contains("shard"));
  CHECK(merged.at("provenance").at("load_average_end") == "shard 1: 1.00 0.50 0.25; shard 2: 2.00 0.50 0.25");

  // Each shard holds only its own part, and records which part it is.
  const Json one = Json::parse(pbr::test::readFile(shards.one));
  CHECK(one.at("shard") == Json{{"index", 1}, {"count", 2}});
  CHECK(one.at("sweep") == expected.at("sweep"));
  CHECK(one.at("configurations").size() == 2);
}

TEST_CASE("bench-merge: --trace lays each shard's timed frames on a process of its own, as the shard ran them") {
  const TempDir dir;
  const BenchSettings settings = tinySweep();
  const Shards shards = writeShards(dir, settings);
  const PbrRun run = merge(dir, {shards.one, shards.two, "--trace", dir.file("trace.json")});
  CAPTURE(run.err);
  REQUIRE(run.exitCode == 0);
  const Json trace = Json::parse(pbr::test::readFile(dir.file("trace.json")));

  // Which shard measured each position of the sweep, and what it measured there.
  const std::vector<pbr::BenchConfig> sweep = pbr::sweepConfigs(settings);
  std::vector<int> shardOf(sweep.size(), 0);
  for (int k = 1; k <= 2; ++k) {
    for (size_t p : pbr::shardPositions(sweep, pbr::BenchShard{k, 2})) shardOf[p] = k;
  }
  std::map<int, std::string> processes;
  std::map<int, std::string> threads;
  std::map<std::pair<int, int>, std::vector<Json>> slices;  // (pid, tid) -> its slices
  for (const Json& e : trace.at("traceEvents")) {
    if (e.at("name") == "process_name") processes[e.at("pid").get<int>()] = e.at("args").at("name");
    if (e.at("name") == "thread_name") threads[e.at("tid").get<int>()] = e.at("args").at("name");
    if (e.at("ph") == "X") slices[{e.at("pid").get<int>(), e.at("tid").get<int>()}].push_back(e);
  }
  REQUIRE(processes.size() == 2);
  CHECK(processes.at(1).find(", shard 1") != std::string::npos);
  CHECK(processes.at(2).find(", shard 2") != std::string::npos);
  REQUIRE(threads.size() == sweep.size());
  for (size_t p = 0; p < sweep.size(); ++p) {
    CAPTURE(p);
    const BenchResult r = measured(sweep[p], p);
    const int tid = static_cast<int>(p) + 1;
    CHECK(threads.at(tid) == sweep[p].label() + (r.skipped ? " (skipped)" : ""));
    const auto found = slices.find({shardOf[p], tid});
    if (r.skipped) {
      CHECK(found == slices.end());
      continue;
    }
    REQUIRE(found != slices.end());
    // Frames where the shard's timeline put them; passes at their recorded offsets inside their frame.
    size_t checked = 0;
    for (const pbr::FrameTiming& f : r.frames) {
      const double frameUs = (r.timelineStartMs + f.startMs - r.frames.front().startMs) * 1e3;
      for (const Json& e : found->second) {
        if (e.at("args").at("frame") != f.frame) continue;
        if (e.at("name") == "frame") {
          CHECK(std::abs(e.at("ts").get<double>() - frameUs) <= 1e-3);  // the trace's nanosecond rounding
          ++checked;
        }
        for (const pbr::PassTiming& pass : f.passes) {
          if (e.at("name") != pass.name) continue;
          CHECK(std::abs(e.at("ts").get<double>() - (frameUs + pass.startMs * 1e3)) <= 1e-3);
          CHECK(std::abs(e.at("dur").get<double>() - pass.ms * 1e3) <= 1e-3);
          ++checked;
        }
      }
    }
    CHECK(checked == found->second.size());
    CHECK(checked == r.frames.size() * (1 + r.frames.front().passes.size()));
  }
}

TEST_CASE("bench-merge: --trace refuses a shard without pass start times, which merges without it") {
  const TempDir dir;
  const Shards shards = writeShards(dir);
  const std::string older = editedCopy(dir, shards.two, "older.json", [](Json& doc) {
    for (Json& c : doc["configurations"]) {
      c.erase("timeline_start_ms");
      for (Json& f : c["frames"]) f.erase("passes_start_ms");
    }
  });
  checkRefusedNaming(merge(dir, {shards.one, older, "--trace", dir.file("trace.json")}), older,
                     "holds no pass start times");
  CHECK_FALSE(std::ifstream(dir.file("trace.json")).good());
  const PbrRun plain = merge(dir, {shards.one, older, "--json", dir.file("merged.json")});
  CAPTURE(plain.err);
  CHECK(plain.exitCode == 0);
}

TEST_CASE("bench-merge: a missing or repeated shard is refused, saying which") {
  const TempDir dir;
  const Shards shards = writeShards(dir);
  const PbrRun missing = merge(dir, {shards.two, "--csv", dir.file("merged.csv")});
  CAPTURE(missing.err);
  CHECK(missing.exitCode == 1);
  pbr::test::checkOneLineNaming(missing, "shard 1 of 2 missing (the files given hold shard 2)");
  CHECK_FALSE(std::ifstream(dir.file("merged.csv")).good());

  const std::string again = dir.write("again.json", pbr::test::readFile(shards.one));
  checkRefusedNaming(merge(dir, {shards.one, shards.two, again}), again, "shard 1/2 again, already given as " + shards.one);
}

TEST_CASE("bench-merge: shards of different sweeps or shard counts are refused, naming the difference") {
  const TempDir dir;
  const Shards shards = writeShards(dir);
  const std::string other =
      writeJson(dir, "other.json", report(tinySweep({4, 16}), pbr::BenchShard{2, 2}, "pbr bench --shard 2/2"));
  checkRefusedNaming(merge(dir, {shards.one, other}), other,
                     "a shard of another sweep than " + shards.one + " (lights [4,8] there, [4,16] here)");

  BenchSettings wider = tinySweep();
  wider.models = {pbr::ShadingModel::Pbr, pbr::ShadingModel::BlinnPhong};
  const std::string three =
      writeJson(dir, "three.json", report(wider, pbr::BenchShard{2, 3}, "pbr bench --shard 2/3"));
  checkRefusedNaming(merge(dir, {shards.one, three}), three,
                     "shard 2/3 of a sweep in 3 shards, but " + shards.one + " is shard 1/2");
}

TEST_CASE("bench-merge: shards from another renderer or build are refused unless --allow-mixed") {
  const TempDir dir;
  const Shards shards = writeShards(dir);
  const std::string gpu = editedCopy(dir, shards.two, "gpu.json",
                                     [](Json& doc) { doc["provenance"]["gl_renderer"] = "Some GPU/PCIe/SSE2"; });
  checkRefusedNaming(merge(dir, {shards.one, gpu}), gpu,
                     "measured with gl_renderer 'Some GPU/PCIe/SSE2', " + shards.one +
                         " with 'llvmpipe (LLVM 15.0.6, 256 bits)' (--allow-mixed merges them anyway)");
  const std::string build = editedCopy(dir, shards.two, "build.json",
                                       [](Json& doc) { doc["provenance"]["git_commit"] = "fedcba98"; });
  checkRefusedNaming(merge(dir, {shards.one, build}), build, "measured with git_commit 'fedcba98'");
  // llvmpipe's times are the CPU's.
  const std::string cpu = editedCopy(dir, shards.two, "cpu.json",
                                     [](Json& doc) { doc["provenance"]["cpu_model"] = "Another CPU"; });
  checkRefusedNaming(merge(dir, {shards.one, cpu}), cpu, "measured with cpu_model 'Another CPU'");

  const PbrRun mixed = merge(dir, {shards.one, gpu, "--allow-mixed", "--json", dir.file("merged.json")});
  CAPTURE(mixed.err);
  REQUIRE(mixed.exitCode == 0);
  const Json merged = Json::parse(pbr::test::readFile(dir.file("merged.json")));
  CHECK(merged.at("provenance").at("gl_renderer") ==
        "shard 1: llvmpipe (LLVM 15.0.6, 256 bits); shard 2: Some GPU/PCIe/SSE2");
}

TEST_CASE("bench-merge: files that are no shard's report are refused with one line naming them") {
  const TempDir dir;
  const Shards shards = writeShards(dir);
  const std::string text = pbr::test::readFile(shards.two);
  const std::string cut = dir.write("cut.json", text.substr(0, text.size() / 2));
  checkRefusedNaming(merge(dir, {shards.one, cut}), cut, "JSON syntax error");

  const std::string whole = writeJson(dir, "whole.json", report(tinySweep(), std::nullopt, "pbr bench"));
  checkRefusedNaming(merge(dir, {whole}), whole, "not a shard's report (written without pbr bench --shard)");

  const std::string schema = dir.write("schema.json", R"({"schema": "pbr-pair-cost/1"})");
  checkRefusedNaming(merge(dir, {schema}), schema, "schema: expected \"pbr-bench/1\"");

  const std::string settings = editedCopy(dir, shards.two, "settings.json",
                                          [](Json& doc) { doc["settings"]["timed_frames"] = 3; });
  checkRefusedNaming(merge(dir, {shards.one, settings}), settings, "the file was edited");

  const std::string dropped = editedCopy(dir, shards.two, "dropped.json",
                                         [](Json& doc) { doc["configurations"].erase(0); });
  checkRefusedNaming(merge(dir, {shards.one, dropped}), dropped,
                     "its configurations are not the 2 that shard 2/2 of its sweep measures");

  const std::string badField = editedCopy(dir, shards.two, "field.json",
                                          [](Json& doc) { doc["configurations"][1]["lights"] = "eight"; });
  checkRefusedNaming(merge(dir, {shards.one, badField}), badField, "configurations[1].lights: expected an integer");

  const std::string absent = dir.file("absent.json");
  checkRefusedNaming(merge(dir, {shards.one, absent}), absent, absent);
}

TEST_CASE("bench-merge: its help and its command-line errors") {
  const TempDir dir;
  const PbrRun help = merge(dir, {"--help"});
  CHECK(help.exitCode == 0);
  CHECK(help.err.empty());
  for (const char* option : {"SHARD.json...", "--csv F", "--json F", "--trace F", "--allow-mixed"}) {
    CAPTURE(option);
    CHECK(help.out.find(option) != std::string::npos);
  }
  const PbrRun top = pbr::test::runPbr(dir, {"--help"});
  CHECK(top.out.find("bench-merge") != std::string::npos);

  for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
           {}, {"--csv", "m.csv"}, {"a.json", "--no-such-option"}, {"a.json", "--csv"}}) {
    const PbrRun run = merge(dir, args);
    CAPTURE(run.err);
    CHECK(run.exitCode == 2);
    CHECK(pbr::test::isOneLine(run.err));
    CHECK(run.out.empty());
  }
}
