// The bench's per-round ratios: each configuration's frames over those of its culling and model at the fewest
// lights, round k against round k, from made-up frames whose ratios are known; and where no such ratio exists.
#include <doctest/doctest.h>

#include <sstream>
#include <string>
#include <vector>

#include "app/bench/round_ratios.hpp"

using pbr::BenchReport;
using pbr::BenchResult;

namespace {

// Frames of the given frame times, the cluster pass taking `clusterShare` of each when clustered.
BenchResult result(int lights, pbr::Culling culling, const std::vector<double>& frameMs, double clusterShare = 0.25) {
  BenchResult r;
  r.config.scene = "stress";
  r.config.lights = lights;
  r.config.culling = culling;
  r.config.model = pbr::ShadingModel::Pbr;
  int index = 0;
  for (double ms : frameMs) {
    pbr::FrameTiming f;
    f.frame = ++index;
    f.gpuMs = ms;
    f.passes.push_back({"gbuffer", ms * (1.0 - clusterShare), 0.0});
    if (culling == pbr::Culling::Clustered) {
      f.passes.push_back({"cluster", ms * clusterShare, ms * (1.0 - clusterShare)});
    }
    r.frames.push_back(f);
  }
  r.summarize();
  return r;
}

BenchReport inTurn(std::vector<BenchResult> results) {
  BenchReport report;
  report.provenance.set("frame_order", "configurations in turn, a timed frame each per round");
  report.results = std::move(results);
  return report;
}

}  // namespace

TEST_CASE("bench ratios: round k over round k of the fewest lights, per culling and model") {
  using pbr::Culling;
  // The base's rounds differ by up to 2x (a machine changing speed); the 8-light frames follow it at 4x, 4.5x, 3x.
  const BenchReport report = inTurn({result(4, Culling::None, {10.0, 20.0, 15.0}),
                                     result(4, Culling::Clustered, {100.0, 200.0, 150.0}, 0.5),
                                     result(8, Culling::None, {20.0, 40.0, 30.0}),
                                     result(8, Culling::Clustered, {400.0, 900.0, 450.0}, 0.5)});
  const std::vector<pbr::RoundRatios> ratios = pbr::roundRatios(report);
  REQUIRE(ratios.size() == 2);
  CHECK(ratios[0].result == &report.results[2]);
  CHECK(ratios[0].base == &report.results[0]);
  CHECK(ratios[0].frame == std::vector<double>{2.0, 2.0, 2.0});
  CHECK(ratios[0].cluster.empty());
  CHECK(ratios[1].base == &report.results[1]);
  CHECK(ratios[1].frame == std::vector<double>{4.0, 4.5, 3.0});
  CHECK(ratios[1].cluster == std::vector<double>{4.0, 4.5, 3.0});

  std::ostringstream out;
  pbr::printRoundRatios(out, report);
  CAPTURE(out.str());
  // The median of the rounds (4.0), not the ratio of the medians (450 / 150 = 3.0).
  CHECK(out.str().find("4.00x (3.00-4.50)") != std::string::npos);
  CHECK(out.str().find("2.00x (2.00-2.00)") != std::string::npos);
}

TEST_CASE("bench ratios: none without a base measured in the same run, or without rounds") {
  using pbr::Culling;
  BenchReport skipped = inTurn({result(4, Culling::Clustered, {}), result(8, Culling::Clustered, {40.0, 50.0})});
  skipped.results[0].skipped = true;
  CHECK(pbr::roundRatios(skipped).empty());

  BenchReport shards = inTurn({result(4, Culling::Clustered, {10.0}), result(8, Culling::Clustered, {40.0})});
  shards.results[0].shard = 1;
  shards.results[1].shard = 2;
  CHECK(pbr::roundRatios(shards).empty());
  shards.results[1].shard = 1;
  CHECK(pbr::roundRatios(shards).size() == 1);

  BenchReport oneAfterAnother = inTurn({result(4, Culling::Clustered, {10.0}), result(8, Culling::Clustered, {40.0})});
  oneAfterAnother.provenance = pbr::Provenance{};
  CHECK(pbr::roundRatios(oneAfterAnother).empty());
  std::ostringstream out;
  pbr::printRoundRatios(out, oneAfterAnother);
  CHECK(out.str().empty());
}
