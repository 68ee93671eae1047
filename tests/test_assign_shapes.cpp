#include <doctest/doctest.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <utility>

#include <glm/gtc/matrix_transform.hpp>

#include "core/scene/builtin_scenes.hpp"
#include "renderer/renderer.hpp"
#include "tests/cluster_test_scene.hpp"
#include "tests/gl_test_context.hpp"
#include "tests/render_util.hpp"

using namespace pbr;

// The assignment passes' shapes (AssignShape): four lights and one list per invocation, a workgroup per light and
// per list, or an invocation per cluster (the light pass). Forced in every combination, they must give the same
// sorted lists, and the frames they shade must equal brute force bit for bit: the light counts and kinds of the
// culling tests, spot lights included.
namespace {

struct Shaded {
  std::vector<std::vector<uint32_t>> lists;
  test::RenderedFrame frame;
};

Shaded shade(const Scene& scene, glm::ivec2 size, AssignShape lightPass, AssignShape fill) {
  ClusterConfig config;
  config.lightPass = lightPass;
  config.fill = fill;
  FrameOptions options;
  options.culling = Culling::Clustered;
  Shaded out;
  out.frame = test::renderScene(scene, size, options, 2, config);
  const ShaderLibrary shaders;
  Renderer renderer(shaders, scene, size.x, size.y, RendererConfig{config});
  Profiler profiler(TimingMode::Serializing);
  renderer.renderFrame({}, profiler);
  renderer.renderFrame({}, profiler);
  out.lists = renderer.clusters().readLists();
  return out;
}

void checkShapesAgree(const Scene& scene, glm::ivec2 size, bool mixed) {
  FrameOptions options;
  options.culling = Culling::None;
  const test::RenderedFrame reference = test::renderScene(scene, size, options, 1);
  std::vector<std::pair<AssignShape, AssignShape>> shapes = {{AssignShape::Invocation, AssignShape::Invocation},
                                                             {AssignShape::Workgroup, AssignShape::Workgroup},
                                                             {AssignShape::Cluster, AssignShape::Workgroup}};
  if (mixed) {
    shapes.push_back({AssignShape::Invocation, AssignShape::Workgroup});
    shapes.push_back({AssignShape::Workgroup, AssignShape::Invocation});
    shapes.push_back({AssignShape::Cluster, AssignShape::Invocation});
  }
  std::vector<std::vector<uint32_t>> first;
  size_t listed = 0;
  for (const auto& [lightPass, fill] : shapes) {
    CAPTURE(scene.lights.size());
    CAPTURE(toString(lightPass));
    CAPTURE(toString(fill));
    const Shaded shaded = shade(scene, size, lightPass, fill);
    CHECK(shaded.frame.stats.overflowedClusters == 0);
    CHECK(test::maxRelativeDifference(shaded.frame.hdr, reference.hdr) == 0.0);
    CHECK(test::countDifferentBytes(shaded.frame.ldr, reference.ldr) == 0);
    if (first.empty()) {
      first = shaded.lists;
      for (const auto& list : first) {
        listed += list.size();
        CHECK(std::is_sorted(list.begin(), list.end()));
      }
    } else {
      CHECK(shaded.lists == first);
    }
  }
  if (!scene.lights.empty()) CHECK(listed > 0);
}

// After `frames` frames with automatic shapes: what the shapes' summary says, and the clusters' status.
std::pair<std::string, ClusterStatus> trialled(const Scene& scene, glm::ivec2 size, int frames) {
  const ShaderLibrary shaders;
  Renderer renderer(shaders, scene, size.x, size.y, RendererConfig{ClusterConfig{}});
  Profiler profiler(TimingMode::Serializing);
  for (int frame = 0; frame < frames; ++frame) renderer.renderFrame({}, profiler);
  return {renderer.clusters().shapeSummary(), renderer.clusters().readStatus()};
}

}  // namespace

TEST_CASE("assignment shapes: every combination lists and shades as brute force, 0 to 4,096 lights, spots included") {
  PBR_REQUIRE_GL();
  checkShapesAgree(test::litClusterScene(0, 1, 0.5f, 4.0f, 0.0f), {160, 90}, true);
  checkShapesAgree(test::litClusterScene(1, 2, 6.0f, 6.0f, 0.0f), {160, 90}, true);
  // Few and large: each light reaches most tiles, the case a workgroup per light is for.
  checkShapesAgree(test::litClusterScene(256, 3, 8.0f, 20.0f, 0.5f), {160, 90}, true);
  checkShapesAgree(test::litClusterScene(4096, 4, 0.5f, 4.0f, 0.3f), {160, 90}, true);
}

TEST_CASE("assignment shapes: 65,536 lights, and masks over their budget in windows, list as the other shape") {
  PBR_REQUIRE_GL();
  checkShapesAgree(test::litClusterScene(65536, 5, 0.3f, 2.0f, 0.2f), {96, 54}, false);
  const Scene scene = test::litClusterScene(3000, 6, 0.5f, 4.0f, 0.0f);
  const auto lists = [&scene](const ClusterConfig& config) {
    const ShaderLibrary shaders;
    Renderer renderer(shaders, scene, 160, 90, RendererConfig{config});
    Profiler profiler(TimingMode::Serializing);
    renderer.renderFrame({}, profiler);
    renderer.renderFrame({}, profiler);
    REQUIRE(renderer.lightStats().overflowedClusters == 0);
    return std::make_pair(renderer.clusters().readLists(), renderer.clusters().windowLights());
  };
  const auto whole = lists(ClusterConfig{});
  REQUIRE(whole.second == scene.lights.size());
  for (const AssignShape shape : {AssignShape::Invocation, AssignShape::Workgroup, AssignShape::Cluster}) {
    ClusterConfig budget;
    budget.maxMaskBytes = 64ull << 10;  // windows of 1,024 lights: a light pass and a fill each
    budget.lightPass = shape;
    budget.fill = shape == AssignShape::Invocation ? shape : AssignShape::Workgroup;
    CAPTURE(toString(shape));
    const auto windowed = lists(budget);
    CHECK(windowed.second < scene.lights.size());
    CHECK(windowed.first == whole.first);
  }
}

TEST_CASE("assignment shapes: 1,048,576 lights on a small frame list as the other shape and shade as brute force") {
  PBR_REQUIRE_GL();
  checkShapesAgree(test::litClusterScene(1 << 20, 7, 0.2f, 1.5f, 0.1f), {24, 14}, false);
}

TEST_CASE("assignment shapes: automatic shapes time each shape on the frames after the first, exact on every frame") {
  PBR_REQUIRE_GL();
  const Scene scene = test::litClusterScene(256, 3, 8.0f, 20.0f, 0.5f);
  FrameOptions options;
  options.culling = Culling::None;
  const test::RenderedFrame reference = test::renderScene(scene, {160, 90}, options, 1);
  options.culling = Culling::Clustered;
  const ShaderLibrary shaders;
  Renderer renderer(shaders, scene, 160, 90, RendererConfig{ClusterConfig{}});
  Profiler profiler(TimingMode::Serializing);
  // The first frame sizes the lists, the next three are the trials; the results come back within a few frames.
  for (int frame = 0; frame < 8; ++frame) {
    ImageRgbaF hdr;
    renderer.renderFrame(options, profiler, FrameCapture{nullptr, &hdr});
    CAPTURE(frame);
    CHECK(test::maxRelativeDifference(hdr, reference.hdr) == 0.0);
  }
  const std::string summary = renderer.clusters().shapeSummary();
  CAPTURE(summary);
  REQUIRE(summary.find("timed here") != std::string::npos);
  // Each pass keeps the shape it timed fastest: three light-pass shapes (256 lights over a few hundred clusters
  // is within the cluster shape's trial), two fills.
  const std::string names[3] = {"invocation", "workgroup", "cluster"};
  for (const auto& [pass, shapes] : {std::pair<std::string, int>{"light pass", 3}, {"fill", 2}}) {
    const size_t at = summary.find(pass + " ");
    REQUIRE(at != std::string::npos);
    double ms[3] = {0.0, 0.0, 0.0};
    const char* format = shapes == 3 ? "%lf / %lf / %lf" : "%lf / %lf";
    REQUIRE(std::sscanf(summary.c_str() + summary.find(pass + " ", summary.find("timed here")) + pass.size(), format,
                        &ms[0], &ms[1], &ms[2]) == shapes);
    const int fastest = int(std::min_element(ms, ms + shapes) - ms);
    CAPTURE(pass);
    CHECK(summary.compare(at + pass.size() + 1, names[fastest].size(), names[fastest]) == 0);
  }
}

TEST_CASE("assignment shapes: over 65,536 lights the automatic choice keeps an invocation's four lights untried") {
  PBR_REQUIRE_GL();
  const std::string summary = trialled(test::litClusterScene(70000, 8, 0.2f, 1.5f, 0.0f), {24, 14}, 6).first;
  CAPTURE(summary);
  CHECK(summary.rfind("light pass invocation, ", 0) == 0);
  CHECK(summary.find("not tried over 65536 lights") != std::string::npos);
  // 70,000 lights over the clusters of a 24x14 frame are past the cluster shape's 4,194,304 tests only if more
  // than 59 clusters hold a surface: this frame's one tile of 192 slices holds fewer, so it is tried.
  CHECK(summary.find("not tried over 4194304 tests") == std::string::npos);
}

TEST_CASE("assignment shapes: the cluster light pass is not tried where lights x occupied clusters is large") {
  PBR_REQUIRE_GL();
  const auto [summary, status] = trialled(test::litClusterScene(8192, 4, 0.5f, 4.0f, 0.0f), {640, 360}, 7);
  REQUIRE(uint64_t(status.activeClusters) * 8192 > AssignShapeTrials::kMaxPerClusterTests);
  CAPTURE(summary);
  CHECK(summary.find("not tried over 4194304 tests") != std::string::npos);
  CHECK(summary.find("light pass cluster") == std::string::npos);
}
