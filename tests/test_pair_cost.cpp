// The cost-per-pair fixture measures what it claims: every light-pixel pair of its frame runs the whole BRDF; on a
// scene (--pair-scene) each variant is timed brute force and clustered, per pair each evaluates.
#include <doctest/doctest.h>

#include "app/accuracy/pair_cost.hpp"
#include "core/scene/builtin_scenes.hpp"
#include "tests/gl_test_context.hpp"
#include "tests/render_util.hpp"

using namespace pbr;

TEST_CASE("pair cost: in the fixture every pixel is surface under the BLEND pane, every light-pixel pair contributes") {
  PBR_REQUIRE_GL();
  const glm::ivec2 size{128, 72};
  for (const ShadingModel model : {ShadingModel::Pbr, ShadingModel::BlinnPhong}) {
    FrameOptions options;
    options.model = model;
    options.culling = Culling::None;
    options.stats = true;
    const test::RenderedFrame f = test::renderScene(pairCostScene(16), size, options);
    CHECK(f.stats.pairs.evaluated == uint64_t(size.x) * size.y * 16);
    CHECK(f.stats.pairs.contributing == f.stats.pairs.evaluated);
    // The pane covers every pixel: the frame differs everywhere from the floor alone (in PBR: Blinn-Phong's LDR
    // clamp saturates both).
    if (model != ShadingModel::Pbr) continue;
    Scene floor = pairCostScene(16);
    floor.objects.pop_back();
    const test::RenderedFrame alone = test::renderScene(floor, size, options);
    for (int y = 0; y < size.y; ++y) {
      for (int x = 0; x < size.x; ++x) {
        const float *a = f.hdr.at(x, y), *b = alone.hdr.at(x, y);
        CHECK((a[0] != b[0] || a[1] != b[1] || a[2] != b[2]));
      }
    }
  }
}

TEST_CASE("pair cost: the measurement returns finite positive spreads for every variant, in the order given") {
  PBR_REQUIRE_GL();
  const ShaderLibrary shaders;
  std::vector<PairCostVariant> variants(2);
  variants[0].name = "pbr";
  variants[1].name = "blinn-phong";
  variants[1].options.model = ShadingModel::BlinnPhong;
  PairCostSettings settings;
  settings.size = {48, 27};
  settings.lights = 4;
  settings.rounds = 3;
  const std::vector<PairCost> costs = measurePairCost(shaders, variants, settings);
  REQUIRE(costs.size() == 2);
  for (size_t i = 0; i < costs.size(); ++i) {
    CHECK(costs[i].name == variants[i].name);
    CHECK(costs[i].pairs == 48u * 27u * 4u);
    CHECK(costs[i].nsPerPair.p10 > 0.0);
    CHECK(costs[i].nsPerPair.p10 <= costs[i].nsPerPair.median);
    CHECK(costs[i].nsPerPair.median <= costs[i].nsPerPair.p90);
    CHECK(costs[i].fixedShare > 0.0);
    CHECK(costs[i].transparentNsPerPair.p10 > 0.0);
    CHECK(costs[i].transparentNsPerPair.p10 <= costs[i].transparentNsPerPair.median);
    CHECK(costs[i].transparentNsPerPair.median <= costs[i].transparentNsPerPair.p90);
    CHECK(costs[i].transparentFixedShare > 0.0);
  }
}

TEST_CASE("pair cost on a scene: each variant brute force and clustered, per pair each evaluates") {
  PBR_REQUIRE_GL();
  const ShaderLibrary shaders;
  SceneParams params;
  params.lights = 32;
  const Scene scene = makeBuiltinScene("default", params);
  std::vector<PairCostVariant> variants(2);
  variants[0].name = variants[1].name = "pbr";
  variants[1].culling = Culling::Clustered;
  PairCostSettings settings;
  settings.size = {64, 36};
  settings.lights = 32;
  settings.rounds = 2;
  settings.scene = "default";
  const std::vector<PairCost> costs = measurePairCost(shaders, variants, settings, &scene);
  REQUIRE(costs.size() == 2);
  CHECK((costs[0].culling == Culling::None));
  CHECK((costs[1].culling == Culling::Clustered));
  // Brute force evaluates every light at every surface pixel; the clusters' lists leave out lights that miss them.
  CHECK(costs[0].pairs % 32u == 0u);
  CHECK(costs[0].pairs <= 64u * 36u * 32u);
  CHECK(costs[1].pairs > 0u);
  CHECK(costs[1].pairs < costs[0].pairs);
  for (const PairCost& c : costs) {
    CHECK(c.nsPerPair.p10 > 0.0);
    CHECK(c.nsPerPair.median <= c.nsPerPair.p90);
    CHECK(c.fixedShare > 0.0);
    CHECK(c.transparentNsPerPair.median == 0.0);  // the fixture's pane only
    CHECK(c.transparentFixedShare == 0.0);
  }
}
