#include <doctest/doctest.h>

#include <cstdio>
#include <string>

#include "renderer/renderer.hpp"
#include "tests/cluster_test_scene.hpp"
#include "tests/gl_test_context.hpp"
#include "tests/render_util.hpp"

using namespace pbr;

// The cluster grid's tile side timed on the machine (TileTrials, ClusterConfig::tileTrial): with long lists the
// finer grid is timed against the configured one and the faster kept, every frame equal to brute force; with short
// lists the finer grid is not tried.
namespace {

struct Trial {
  std::string summary;
  glm::uvec3 dims{0};
  double listLength = 0.0;
};

// `frames` frames of clustered culling with the tile side timed from `tile` pixels, each checked against brute force.
Trial runTrial(const Scene& scene, glm::ivec2 size, int tile, int frames) {
  FrameOptions options;
  options.culling = Culling::None;
  const test::RenderedFrame reference = test::renderScene(scene, size, options, 1);
  options.culling = Culling::Clustered;
  RendererConfig config;
  config.clusters.tileSize = tile;
  config.clusters.tileTrial = true;
  const ShaderLibrary shaders;
  Renderer renderer(shaders, scene, size.x, size.y, config);
  Profiler profiler(TimingMode::Serializing);
  for (int frame = 0; frame < frames; ++frame) {
    ImageRgbaF hdr;
    renderer.renderFrame(options, profiler, FrameCapture{nullptr, &hdr});
    CAPTURE(frame);
    CHECK(test::maxRelativeDifference(hdr, reference.hdr) == 0.0);
  }
  const ClusterStatus status = renderer.clusters().readStatus();
  return {renderer.tileSummary(), renderer.clusters().dims(),
          status.activeClusters ? double(status.demand) / status.activeClusters : 0.0};
}

}  // namespace

TEST_CASE("tile trials: with long lists the half side is timed and the faster kept, every frame exact") {
  PBR_REQUIRE_GL();
  const glm::ivec2 size{192, 108};
  const Trial t = runTrial(test::litClusterScene(2048, 11, 3.0f, 6.0f, 0.0f), size, 32, 24);
  CAPTURE(t.summary);
  REQUIRE(t.summary.find("timed here") != std::string::npos);
  int chosen = 0, base = 0, fine = 0;
  double baseMs = 0.0, fineMs = 0.0;
  REQUIRE(std::sscanf(t.summary.c_str(), "%d-pixel tiles (timed here, cluster pass to lighting pass: %d px %lf ms, %d "
                      "px %lf ms)", &chosen, &base, &baseMs, &fine, &fineMs) == 5);
  CHECK(base == 32);
  CHECK(fine == 16);
  CHECK(chosen == (fineMs < baseMs ? fine : base));
  // The grid the clusters hold is the chosen side's.
  CHECK(t.dims.x == unsigned((size.x + chosen - 1) / chosen));
  CHECK(t.dims.y == unsigned((size.y + chosen - 1) / chosen));
}

TEST_CASE("tile trials: with short lists the half side is not tried") {
  PBR_REQUIRE_GL();
  const Trial t = runTrial(test::litClusterScene(64, 11, 0.5f, 1.5f, 0.0f), {192, 108}, 32, 8);
  CAPTURE(t.summary);
  CHECK(t.listLength < TileTrials::kMinListLength);
  CHECK(t.summary.find("32-pixel tiles (16-pixel ones not tried: ") == 0);
  CHECK(t.dims.x == 6u);
}
