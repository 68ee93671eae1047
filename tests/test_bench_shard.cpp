// `pbr bench --shard K/N`: which configurations each shard measures, and the command lines refused before any
// context is made.
#include <doctest/doctest.h>

#include <algorithm>
#include <set>
#include <string>
#include <vector>

#include "app/args.hpp"
#include "app/bench/bench_shard.hpp"
#include "tests/cli_util.hpp"
#include "tests/refusal_checks.hpp"

using pbr::BenchConfig;
using pbr::BenchSettings;
using pbr::BenchShard;

namespace {

std::vector<BenchSettings> sweeps() {
  BenchSettings standard;  // 5 light counts x 2 culling modes x 2 models
  BenchSettings oneModel;
  oneModel.lights = {4, 8, 16, 32, 64, 128, 256};
  oneModel.culling = {pbr::Culling::Clustered};
  oneModel.models = {pbr::ShadingModel::Pbr};
  BenchSettings descending;
  descending.lights = {4096, 64, 1024};
  descending.models = {pbr::ShadingModel::BlinnPhong};
  return {standard, oneModel, descending};
}

}  // namespace

TEST_CASE("bench shard: the shards of a sweep are disjoint, cover it and differ in size by at most one") {
  for (const BenchSettings& settings : sweeps()) {
    const std::vector<BenchConfig> sweep = pbr::sweepConfigs(settings);
    REQUIRE(sweep.size() == settings.lights.size() * settings.culling.size() * settings.models.size());
    for (int count = 1; count <= static_cast<int>(sweep.size()); ++count) {
      CAPTURE(sweep.size());
      CAPTURE(count);
      std::vector<int> owners(sweep.size(), 0);
      size_t smallest = sweep.size(), largest = 0;
      for (int index = 1; index <= count; ++index) {
        const std::vector<size_t> positions = pbr::shardPositions(sweep, {index, count});
        CHECK(std::is_sorted(positions.begin(), positions.end()));
        for (size_t p : positions) {
          REQUIRE(p < sweep.size());
          ++owners[p];
        }
        smallest = std::min(smallest, positions.size());
        largest = std::max(largest, positions.size());
      }
      CHECK(std::all_of(owners.begin(), owners.end(), [](int n) { return n == 1; }));
      CHECK(smallest >= 1);
      CHECK(largest - smallest <= 1);
    }
  }
}

TEST_CASE("bench shard: each of 4 shards of the standard sweep gets each culling mode, light counts mixed") {
  const std::vector<BenchConfig> sweep = pbr::sweepConfigs(BenchSettings{});
  REQUIRE(sweep.size() == 30);
  for (int index = 1; index <= 4; ++index) {
    CAPTURE(index);
    std::set<pbr::Culling> culling;
    std::set<int> lights;
    int atMost = 0;
    for (size_t p : pbr::shardPositions(sweep, {index, 4})) {
      culling.insert(sweep[p].culling);
      lights.insert(sweep[p].lights);
      atMost += sweep[p].lights == 16384;
    }
    CHECK(culling.size() == 3);
    CHECK(lights.size() == 5);
    CHECK(atMost <= 2);  // the six most expensive configurations spread over the four shards
  }
}

TEST_CASE("bench shard: K/N parses with 1 <= K <= N, anything else is a usage error naming --shard") {
  const BenchShard shard = pbr::parseShard("3/7");
  CHECK(shard.index == 3);
  CHECK(shard.count == 7);
  CHECK(shard.text() == "3/7");
  CHECK(pbr::parseShard("1/1").count == 1);
  for (const char* bad : {"0/2", "3/2", "x", "1/0", "1/", "/2", "2", " 1/2", "+1/2", "1/2 ", "-1/2", "1/2/3", "1.0/2",
                          "1/1048577", "1/99999999999"}) {
    CAPTURE(bad);
    CHECK_THROWS_WITH_AS(pbr::parseShard(bad), doctest::Contains("--shard expects K/N"), pbr::UsageError);
  }
}

TEST_CASE("bench shard: a malformed --shard, one with --pair-cost or more shards than configurations exit 2") {
  const pbr::test::TempDir dir;
  const std::vector<std::string> tiny = {"bench",  "--scene", "default", "--lights", "4,8", "--culling",
                                         "none,clustered", "--model", "pbr", "--size", "32x32"};
  struct Case {
    std::vector<std::string> args;
    std::string message;
  };
  const std::vector<Case> cases = {
      {{"--shard", "0/2"}, "--shard expects K/N, shard K of N with 1 <= K <= N <= 1048576, got '0/2'"},
      {{"--shard", "3/2"}, "got '3/2'"},
      {{"--shard", "x"}, "got 'x'"},
      {{"--shard", "1/0"}, "got '1/0'"},
      {{"--shard", "5/5"}, "--shard 5/5: the sweep has 4 configurations, too few for 5 shards"},
  };
  for (const Case& c : cases) {
    std::vector<std::string> args = tiny;
    args.insert(args.end(), c.args.begin(), c.args.end());
    CAPTURE(c.args[1]);
    const pbr::test::PbrRun run = pbr::test::runPbr(dir, args);
    CHECK(run.exitCode == 2);
    pbr::test::checkOneLineNaming(run, c.message);
    CHECK(run.out.empty());
  }
  const pbr::test::PbrRun pairCost = pbr::test::runPbr(dir, {"bench", "--pair-cost", "default", "--shard", "1/2"});
  CHECK(pairCost.exitCode == 2);
  pbr::test::checkOneLineNaming(pairCost, "--shard belongs to the sweep, not --pair-cost");
}
