// `pbr bench` through the real binary: its CSV, JSON and trace files, skipping by estimate, the charts
// scripts/plot_bench.py draws from the CSV, and a sweep run as shards under GNU parallel then merged.
#include <doctest/doctest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/bench/csv_provenance.hpp"
#include "tests/cli_util.hpp"
#include "tests/gl_test_context.hpp"

using pbr::test::PbrRun;
using pbr::test::TempDir;
using Json = nlohmann::json;

namespace {

// What a report must say about the circumstances of its run, in the CSV's provenance file and in JSON.
const char* const kProvenanceKeys[] = {"command",     "run_date_utc", "gl_renderer", "gl_version",
                                       "gl_vendor",   "egl_platform", "timing_mode", "timing_note",
                                       "cpu_model",   "cpu_cores",    "build_type",  "git_commit",
                                       "git_commit_date"};

struct Csv {
  std::map<std::string, std::string> provenance;
  std::vector<std::string> header;
  std::vector<std::map<std::string, std::string>> rows;
};

// RFC 4180 fields: quoted where they hold a comma or a quote.
std::vector<std::string> splitCsvLine(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
      fields.back() += '"';
      ++i;
    } else if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  return fields;
}

// A CSV `pbr` wrote and the provenance file beside it (F.provenance.txt): the CSV starts with its header row.
Csv readCsv(const std::string& path) {
  Csv csv;
  std::istringstream in(pbr::test::readFile(path));
  for (std::string line; std::getline(in, line);) {
    REQUIRE_MESSAGE(line.rfind('#', 0) != 0, line);
    if (csv.header.empty()) {
      csv.header = splitCsvLine(line);
    } else {
      const std::vector<std::string> fields = splitCsvLine(line);
      REQUIRE_MESSAGE(fields.size() == csv.header.size(), line);
      std::map<std::string, std::string> row;
      for (size_t i = 0; i < fields.size(); ++i) row[csv.header[i]] = fields[i];
      csv.rows.push_back(row);
    }
  }
  std::istringstream provenance(pbr::test::readFile(pbr::provenancePath(path)));
  for (std::string line; std::getline(provenance, line);) {
    const size_t colon = line.find(": ");
    REQUIRE_MESSAGE(colon != std::string::npos, line);
    csv.provenance[line.substr(0, colon)] = line.substr(colon + 2);
  }
  return csv;
}

bool isNumber(const std::string& s) {
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  return !s.empty() && *end == '\0' && std::isfinite(v);
}

// Two light counts, both culling modes, tiny frames: a second or less on llvmpipe.
PbrRun runTinySweep(const TempDir& dir, const std::vector<std::string>& extra = {}, int frames = 2) {
  std::vector<std::string> args = {"bench",     "--lights", "16,64",   "--culling", "none,clustered",
                                   "--model",   "pbr",      "--size",  "160x90",    "--warmup",
                                   "1",         "--frames", std::to_string(frames), "--csv", dir.file("bench.csv"),
                                   "--json",    dir.file("bench.json"), "--trace",  dir.file("trace.json")};
  args.insert(args.end(), extra.begin(), extra.end());
  return pbr::test::runPbr(dir, args);
}

// Runs a shell command, returning its exit status and what it wrote to stdout and stderr.
PbrRun runShell(const TempDir& dir, const std::string& command) {
  const std::string redirected = command + " >" + dir.file("cmd_out.txt") + " 2>&1";
  const int status = std::system(redirected.c_str());
  PbrRun run;
  run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.out = pbr::test::readFile(dir.file("cmd_out.txt"));
  return run;
}

}  // namespace

TEST_CASE("bench: a tiny sweep writes CSV and JSON with every column filled and their provenance") {
  PBR_REQUIRE_GL();
  const TempDir dir;
  const PbrRun run = runTinySweep(dir);
  CAPTURE(run.err);
  REQUIRE(run.exitCode == 0);
  CHECK(run.out.find("lighting") != std::string::npos);  // the table

  const Csv csv = readCsv(dir.file("bench.csv"));
  for (const char* key : kProvenanceKeys) {
    CAPTURE(key);
    REQUIRE(csv.provenance.count(key) == 1);
    CHECK_FALSE(csv.provenance.at(key).empty());
  }
  CHECK(csv.provenance.at("command").find("bench --lights 16,64") != std::string::npos);
  CHECK(csv.provenance.at("run_date_utc").size() == 20);  // 2024-05-01T12:00:00Z
  REQUIRE(csv.rows.size() == 4);
  for (const auto& row : csv.rows) {
    CAPTURE(row.at("lights"));
    CAPTURE(row.at("culling"));
    CHECK(row.at("status") == "ok");
    CHECK(row.at("timed_frames") == "2");
    for (const auto& [column, value] : row) {
      CAPTURE(column);
      CHECK_FALSE(value.empty());
      if (column.size() > 3 && column.compare(column.size() - 3, 3, "_ms") == 0) {
        // Only the cluster pass of a brute-force frame does not exist.
        if (row.at("culling") == "none" && column.rfind("cluster_", 0) == 0) {
          CHECK(value == "n/a");
        } else {
          REQUIRE(isNumber(value));
          CHECK(std::stod(value) >= 0.0);
        }
      }
    }
    CHECK(std::stod(row.at("gbuffer_bytes")) > 0.0);
    // 32 bytes a light, in whole windows of 2,048 lights (64 KiB, the uniform block of the brute-force path).
    const double windows = std::max(1.0, std::ceil(std::stod(row.at("lights")) / 2048.0));
    CHECK(std::stod(row.at("light_bytes")) == windows * 2048.0 * 32.0);
    if (row.at("culling") == "clustered") {
      CHECK(isNumber(row.at("avg_lights_per_cluster")));
      // --tile auto: the configured 64 pixels, or half of it where timed faster.
      CHECK((row.at("tile_size") == "64" || row.at("tile_size") == "32"));
      CHECK(std::stod(row.at("non_empty_clusters")) > 0.0);
      CHECK(std::stod(row.at("cluster_bytes")) > 0.0);
    }
    const double efficiency = std::stod(row.at("culling_efficiency"));
    CHECK(efficiency >= 0.0);
    CHECK(efficiency <= 1.0);
    // The lighting pass's median over its evaluated pairs, in ns, from the row's own columns.
    const double pairs = std::stod(row.at("pairs_evaluated"));
    REQUIRE(pairs > 0.0);
    CHECK(std::stod(row.at("lighting_ns_per_pair")) ==
          doctest::Approx(std::stod(row.at("lighting_median_ms")) * 1e6 / pairs).epsilon(1e-3));
  }

  const Json json = Json::parse(pbr::test::readFile(dir.file("bench.json")));
  CHECK(json.at("schema") == "pbr-bench/1");
  for (const char* key : kProvenanceKeys) {
    CAPTURE(key);
    CHECK(json.at("provenance").at(key).get<std::string>() == csv.provenance.at(key));
  }
  REQUIRE(json.at("configurations").size() == 4);
  for (const Json& c : json.at("configurations")) {
    CAPTURE(c.at("label").get<std::string>());
    CHECK(c.at("status") == "ok");
    CHECK(c.at("skip_reason").is_null());
    for (const char* pass : {"gbuffer", "lighting", "post"}) CHECK(c.at("passes").at(pass).at("median_ms") >= 0.0);
    CHECK(c.at("passes").at("cluster").is_null() == (c.at("culling") == "none"));
    CHECK(c.at("frame").at("p90_ms") >= c.at("frame").at("p10_ms"));
    REQUIRE(c.at("frames").size() == 2);
    for (const Json& f : c.at("frames")) CHECK(f.at("passes_ms").at("lighting") >= 0.0);
    CHECK(c.at("light_stats").at("lights") == c.at("lights"));
    CHECK(c.at("light_stats").at("lighting_ns_per_pair").get<double>() ==
          doctest::Approx(c.at("passes").at("lighting").at("median_ms").get<double>() * 1e6 /
                          c.at("light_stats").at("pairs_evaluated").get<double>())
              .epsilon(1e-9));
    CHECK(c.at("memory_bytes").at("total") > 0);
  }
}

TEST_CASE("bench: --shadows on shadows every light, and each configuration reports its shadow pass and views") {
  PBR_REQUIRE_GL();
  const TempDir dir;
  const PbrRun run = runTinySweep(dir, {"--shadows", "on", "--shadow-atlas", "1024"});
  CAPTURE(run.err);
  REQUIRE(run.exitCode == 0);
  const Csv csv = readCsv(dir.file("bench.csv"));
  CHECK(csv.provenance.at("shadows") == "on");
  CHECK(csv.provenance.at("shadow_atlas") == "1024");
  REQUIRE(csv.rows.size() == 4);
  const Json json = Json::parse(pbr::test::readFile(dir.file("bench.json")));
  CHECK(json.at("settings").at("shadows") == "on");
  for (size_t i = 0; i < csv.rows.size(); ++i) {
    const auto& row = csv.rows[i];
    CAPTURE(row.at("lights"));
    CAPTURE(row.at("culling"));
    REQUIRE(isNumber(row.at("shadow_median_ms")));
    CHECK(std::stod(row.at("shadow_median_ms")) >= 0.0);
    // The random lights are point lights: six cube faces each, rendered or skipped (no receiver in view).
    const int lights = std::stoi(row.at("lights"));
    CHECK(std::stoi(row.at("shadowed_lights")) == lights);
    CHECK(std::stoi(row.at("shadow_views_rendered")) + std::stoi(row.at("shadow_views_skipped")) == 6 * lights);
    CHECK(std::stoi(row.at("shadow_views_rendered")) > 0);
    const Json& stats = json.at("configurations").at(i).at("light_stats");
    CHECK(stats.at("shadow_views_rendered").get<int>() == std::stoi(row.at("shadow_views_rendered")));
  }
}

TEST_CASE("bench: the trace is Chrome trace-event JSON with one slice per pass per timed frame") {
  PBR_REQUIRE_GL();
  const TempDir dir;
  const PbrRun run = runTinySweep(dir);
  CAPTURE(run.err);
  REQUIRE(run.exitCode == 0);
  const Json trace = Json::parse(pbr::test::readFile(dir.file("trace.json")));
  REQUIRE(trace.at("traceEvents").is_array());
  std::map<int, int> slicesPerThread;
  int threadNames = 0;
  for (const Json& e : trace.at("traceEvents")) {
    CAPTURE(e.dump());
    for (const char* key : {"name", "ph", "pid", "tid"}) REQUIRE(e.contains(key));
    if (e.at("ph") == "M") {
      threadNames += e.at("name") == "thread_name";
      continue;
    }
    REQUIRE(e.at("ph") == "X");
    for (const char* key : {"cat", "ts", "dur"}) REQUIRE(e.contains(key));
    CHECK(e.at("ts").get<double>() >= 0.0);
    CHECK(e.at("dur").get<double>() >= 0.0);
    ++slicesPerThread[e.at("tid").get<int>()];
  }
  CHECK(threadNames == 4);
  REQUIRE(slicesPerThread.size() == 4);
  // Per timed frame: the frame, G-buffer, lighting and post, plus the cluster pass when clustered.
  for (const auto& [tid, slices] : slicesPerThread) CHECK((slices == 2 * 4 || slices == 2 * 5));
}

TEST_CASE("bench: the sweep takes its configurations' timed frames in turn, a frame each per round") {
  PBR_REQUIRE_GL();
  const TempDir dir;
  const PbrRun run = runTinySweep(dir, {}, 3);
  CAPTURE(run.err);
  REQUIRE(run.exitCode == 0);
  const Json trace = Json::parse(pbr::test::readFile(dir.file("trace.json")));
  std::vector<std::pair<double, int>> frames;  // start, configuration
  for (const Json& e : trace.at("traceEvents")) {
    if (e.at("ph") == "X" && e.at("name") == "frame") {
      frames.emplace_back(e.at("ts").get<double>(), e.at("tid").get<int>());
    }
  }
  std::sort(frames.begin(), frames.end());
  std::vector<int> order;
  for (const auto& frame : frames) order.push_back(frame.second);
  CHECK(order == std::vector<int>{1, 2, 3, 4, 1, 2, 3, 4, 1, 2, 3, 4});
  const Json report = Json::parse(pbr::test::readFile(dir.file("bench.json")));
  CHECK(report.at("provenance").at("frame_order").get<std::string>().find("in turn") != std::string::npos);
}

TEST_CASE("bench: plot_bench.py draws PNG charts from the CSV") {
  PBR_REQUIRE_GL();
  const TempDir dir;
  if (runShell(dir, "/usr/bin/python3 -c 'import matplotlib'").exitCode != 0) {
    FAIL("/usr/bin/python3 cannot import matplotlib: install the Debian package python3-matplotlib "
         "(scripts/install-deps.sh does)");
  }
  REQUIRE(runTinySweep(dir).exitCode == 0);
  const PbrRun plot = runShell(dir, "/usr/bin/python3 " + std::string(PBR_SOURCE_DIR) + "/scripts/plot_bench.py " +
                                        dir.file("bench.csv") + " --out " + dir.file("charts"));
  CAPTURE(plot.out);
  REQUIRE(plot.exitCode == 0);
  for (const char* chart : {"perf-frame-time.png", "perf-passes.png", "perf-speedup.png"}) {
    CAPTURE(chart);
    const std::string png = pbr::test::readFile(dir.path() / "charts" / chart);
    REQUIRE(png.size() > 8);
    CHECK(png.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0);
  }
}

TEST_CASE("bench: --max-seconds skips configurations estimated to take longer, and says so everywhere") {
  PBR_REQUIRE_GL();
  const TempDir dir;
  const PbrRun run = runTinySweep(dir, {"--max-seconds", "0.001"});
  CAPTURE(run.err);
  REQUIRE(run.exitCode == 0);
  CHECK(run.out.find("skipped") != std::string::npos);

  const Csv csv = readCsv(dir.file("bench.csv"));
  REQUIRE(csv.rows.size() == 4);
  for (const auto& row : csv.rows) {
    CHECK(row.at("status") == "skipped");
    CHECK(row.at("skip_reason").find("--max-seconds") != std::string::npos);
    CHECK(row.at("timed_frames") == "0");
    CHECK(row.at("lighting_median_ms") == "skipped");
    CHECK(row.at("culling_efficiency") == "skipped");
    CHECK(std::stod(row.at("estimated_s")) > 0.001);
  }
  const Json json = Json::parse(pbr::test::readFile(dir.file("bench.json")));
  for (const Json& c : json.at("configurations")) {
    CHECK(c.at("status") == "skipped");
    CHECK(c.at("skip_reason").get<std::string>().find("--max-seconds") != std::string::npos);
    CHECK(c.at("frames").empty());
    CHECK(c.at("passes").is_null());
  }
}

TEST_CASE("bench: --constant-density scales light radii by sqrt(smallest light count / lights)") {
  PBR_REQUIRE_GL();
  const TempDir dir;
  std::vector<Csv> sweeps;
  for (bool constantDensity : {false, true}) {
    std::vector<std::string> args = {"bench",  "--lights", "256,4096", "--culling", "clustered", "--model", "pbr",
                                     "--size", "160x90",   "--warmup", "1",         "--frames",  "1",
                                     "--csv",  dir.file("bench.csv")};
    if (constantDensity) args.push_back("--constant-density");
    const PbrRun run = pbr::test::runPbr(dir, args);
    CAPTURE(run.err);
    REQUIRE(run.exitCode == 0);
    sweeps.push_back(readCsv(dir.file("bench.csv")));
    REQUIRE(sweeps.back().rows.size() == 2);
  }
  const auto avg = [&](size_t sweep, size_t row) {
    return std::stod(sweeps[sweep].rows[row].at("avg_lights_per_cluster"));
  };
  CHECK(sweeps[0].provenance.at("constant_density") == "no");
  CHECK(std::stod(sweeps[0].rows[0].at("light_radius_scale")) == 1.0);
  CHECK(sweeps[1].provenance.at("constant_density") == "yes (light radii x sqrt(256/lights))");
  CHECK(std::stod(sweeps[1].rows[0].at("light_radius_scale")) == doctest::Approx(1.0));
  CHECK(std::stod(sweeps[1].rows[1].at("light_radius_scale")) == doctest::Approx(0.25));
  // The reference count's lights keep their radii; smaller ones above it: the clusters see it.
  CHECK(avg(1, 0) == avg(0, 0));
  CHECK(avg(1, 1) < avg(0, 1));
}

TEST_CASE("bench: --pair-cost measures finite, positive ns per light-pixel pair with ordered spreads in CSV and JSON") {
  const TempDir dir;
  const PbrRun run = pbr::test::runPbr(dir, {"bench", "--pair-cost", "default,blinn-phong", "--size", "64x36", "--pair-lights", "8",
                               "--rounds", "3", "--csv", dir.file("pairs.csv"), "--json", dir.file("pairs.json")});
  REQUIRE(run.exitCode == 0);
  CHECK(run.out.find("cost per light-pixel pair") != std::string::npos);
  const nlohmann::json doc = nlohmann::json::parse(pbr::test::readFile(dir.file("pairs.json")));
  CHECK(doc["schema"] == "pbr-pair-cost/1");
  REQUIRE(doc["variants"].size() == 2);
  for (const nlohmann::json& v : doc["variants"]) {
    CAPTURE(v.dump());
    const double p10 = v["ns_per_pair"]["p10"], med = v["ns_per_pair"]["median"], p90 = v["ns_per_pair"]["p90"];
    CHECK(std::isfinite(p10));
    CHECK(std::isfinite(p90));
    CHECK(p10 > 0.0);
    CHECK(p10 <= med);
    CHECK(med <= p90);
    CHECK(v["pairs_per_frame"] == 64 * 36 * 8);
  }
  const std::string csv = pbr::test::readFile(dir.file("pairs.csv"));
  CHECK(csv.find("variant,material,model,terms,hdr_format,gbuffer,width,height,lights,rounds,ns_per_pair_median,"
                 "ns_per_pair_p10,ns_per_pair_p90") != std::string::npos);
  CHECK(csv.find("\nblinn-phong,core,blinn-phong,") != std::string::npos);
}

TEST_CASE("bench: --pair-materials times each variant on the fixture with each glTF extension's lobe") {
  const TempDir dir;
  const PbrRun run = pbr::test::runPbr(dir, {"bench", "--pair-cost", "default", "--pair-materials",
                                             "core,specular,clearcoat,sheen", "--size", "32x18", "--pair-lights", "4",
                                             "--rounds", "1", "--json", dir.file("pairs.json")});
  REQUIRE(run.exitCode == 0);
  const nlohmann::json doc = nlohmann::json::parse(pbr::test::readFile(dir.file("pairs.json")));
  REQUIRE(doc["variants"].size() == 4);
  const char* materials[] = {"core", "specular", "clearcoat", "sheen"};
  for (size_t i = 0; i < 4; ++i) {
    CHECK(doc["variants"][i]["variant"] == "default");
    CHECK(doc["variants"][i]["material"] == materials[i]);
    const double median = doc["variants"][i]["ns_per_pair"]["median"];
    CHECK(std::isfinite(median));
    CHECK(median > 0.0);
  }
  const PbrRun bad = pbr::test::runPbr(dir, {"bench", "--pair-cost", "default", "--pair-materials", "velvet"});
  CHECK(bad.exitCode == 2);
  CHECK(bad.err.find("unknown fixture material 'velvet'") != std::string::npos);
}

TEST_CASE("bench: --pair-scene times each variant brute force and clustered on the scene, per evaluated pair") {
  const TempDir dir;
  const PbrRun run = pbr::test::runPbr(dir, {"bench", "--pair-cost", "blinn-phong", "--pair-scene", "default",
                                             "--size", "32x18", "--pair-lights", "8", "--rounds", "1", "--json",
                                             dir.file("pairs.json"), "--csv", dir.file("pairs.csv")});
  REQUIRE(run.exitCode == 0);
  const nlohmann::json doc = nlohmann::json::parse(pbr::test::readFile(dir.file("pairs.json")));
  CHECK(doc["settings"]["scene"] == "default");
  REQUIRE(doc["variants"].size() == 2);
  CHECK(doc["variants"][0]["culling"] == "none");
  CHECK(doc["variants"][1]["culling"] == "clustered");
  CHECK(doc["variants"][1]["pairs_per_frame"].get<uint64_t>() < doc["variants"][0]["pairs_per_frame"].get<uint64_t>());
  CHECK(doc["variants"][0]["transparent_ns_per_pair"].is_null());
  const std::string csv = pbr::test::readFile(dir.file("pairs.csv"));
  CHECK(csv.find(",scene,culling\n") != std::string::npos);
  CHECK(csv.find(",default,clustered\n") != std::string::npos);
  const PbrRun bad = pbr::test::runPbr(dir, {"bench", "--pair-cost", "default", "--pair-scene", "default",
                                             "--pair-materials", "sheen"});
  CHECK(bad.exitCode == 2);
  CHECK(bad.err.find("--pair-materials belongs to the fixture, not --pair-scene") != std::string::npos);
}

TEST_CASE("bench: a sweep run as 2 shards under GNU parallel merges into the rows and keys of the unsharded run") {
  PBR_REQUIRE_GL();
  const TempDir dir;
  if (runShell(dir, "command -v parallel").exitCode != 0) {
    MESSAGE("GNU parallel is not installed (Debian package parallel, which scripts/install-deps.sh installs): "
            "skipping the sharded sweep");
    return;
  }
  const std::vector<std::string> sweep = {"bench",  "--scene", "default", "--lights", "4,8",    "--culling",
                                          "none,clustered", "--model", "pbr", "--size", "32x32", "--warmup",
                                          "1",      "--frames", "1"};
  std::vector<std::string> whole = sweep;
  whole.insert(whole.end(), {"--csv", dir.file("whole.csv"), "--json", dir.file("whole.json")});
  const PbrRun unsharded = pbr::test::runPbr(dir, whole);
  CAPTURE(unsharded.err);
  REQUIRE(unsharded.exitCode == 0);
  // Not a terminal: each configuration's line says the time left, but the last one's.
  CHECK(std::regex_search(unsharded.err, std::regex("bench 1/4 4 lights, none, pbr: .*, about [0-9]+ s left\n")));
  CHECK(std::regex_search(unsharded.err, std::regex("bench 4/4 8 lights, clustered, pbr: [^\n]* s\n")));

  std::string command = "parallel --will-cite --halt now,fail=1 " + std::string(PBR_BINARY);
  for (const std::string& arg : sweep) command += " " + arg;
  command += " --shard {}/2 --json " + dir.file("shard-{}.json") + " ::: 1 2";
  const PbrRun shards = runShell(dir, command);
  CAPTURE(shards.out);
  REQUIRE(shards.exitCode == 0);
  const PbrRun merge = pbr::test::runPbr(dir, {"bench-merge", dir.file("shard-1.json"), dir.file("shard-2.json"),
                                                "--csv", dir.file("merged.csv"), "--json", dir.file("merged.json")});
  CAPTURE(merge.err);
  REQUIRE(merge.exitCode == 0);

  const char* const configColumns[] = {"scene", "width", "height", "lights", "culling", "model",
                                       "light_radius_scale", "status", "timed_frames"};
  const Csv expected = readCsv(dir.file("whole.csv"));
  const Csv merged = readCsv(dir.file("merged.csv"));
  CHECK(merged.header == expected.header);
  REQUIRE(merged.rows.size() == 4);
  REQUIRE(merged.rows.size() == expected.rows.size());
  for (size_t i = 0; i < merged.rows.size(); ++i) {
    CAPTURE(i);
    for (const char* column : configColumns) CHECK(merged.rows[i].at(column) == expected.rows[i].at(column));
  }
  for (const char* setting : {"scene", "size", "lights", "culling", "models", "warmup_frames", "timed_frames",
                              "sweep_configurations", "sweep_fingerprint", "gl_renderer", "git_commit"}) {
    CAPTURE(setting);
    CHECK(merged.provenance.at(setting) == expected.provenance.at(setting));
  }

  const Json wholeJson = Json::parse(pbr::test::readFile(dir.file("whole.json")));
  const Json mergedJson = Json::parse(pbr::test::readFile(dir.file("merged.json")));
  for (const char* key : {"schema", "settings", "sweep"}) CHECK(mergedJson.at(key) == wholeJson.at(key));
  CHECK_FALSE(mergedJson.contains("shard"));
  const Json& configs = mergedJson.at("configurations");
  REQUIRE(configs.size() == wholeJson.at("configurations").size());
  for (size_t i = 0; i < configs.size(); ++i) {
    const Json& want = wholeJson.at("configurations")[i];
    CAPTURE(want.at("label").get<std::string>());
    std::vector<std::string> keys, wantKeys;
    for (const auto& [key, value] : configs[i].items()) keys.push_back(key);
    for (const auto& [key, value] : want.items()) wantKeys.push_back(key);
    CHECK(keys == wantKeys);
    for (const char* key : {"label", "scene", "width", "height", "lights", "culling", "model", "light_radius_scale",
                            "status"}) {
      CHECK(configs[i].at(key) == want.at(key));
    }
  }

  // The shards measured disjoint halves of the sweep, each saying which half.
  std::set<std::string> labels;
  for (int k = 1; k <= 2; ++k) {
    const Json shard = Json::parse(pbr::test::readFile(dir.file("shard-" + std::to_string(k) + ".json")));
    CHECK(shard.at("shard") == Json{{"index", k}, {"count", 2}});
    CHECK(shard.at("configurations").size() == 2);
    for (const Json& c : shard.at("configurations")) labels.insert(c.at("label").get<std::string>());
  }
  CHECK(labels.size() == 4);
}
