#include <doctest/doctest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "core/scene/builtin_scenes.hpp"
#include "renderer/renderer.hpp"
#include "tests/gl_test_context.hpp"
#include "tests/render_util.hpp"

using namespace pbr;

// The clusters' light masks past their memory budget: lights assigned in windows (a counting light pass, then a
// marking pass and a fill per window), and clusters past the slots the budget holds shaded by brute force. Both
// must leave the frame exactly as one window with every cluster slotted leaves it.
namespace {

constexpr int kWidth = 160, kHeight = 90;

// A floor and a few boxes lit by 3,000 lights of radii up to 4 m: many clusters hold a surface, most lists are
// non-empty, and several windows of 1,024 lights each reach them.
Scene windowScene() {
  Scene scene;
  scene.camera.position = {0.5f, 2.5f, 6.0f};
  scene.camera.target = {0.0f, 0.0f, -3.0f};
  scene.camera.nearPlane = 0.2f;
  scene.camera.farPlane = 60.0f;
  scene.addShape(Shape::Plane, glm::scale(glm::mat4(1.0f), glm::vec3(60.0f, 1.0f, 60.0f)), {});
  for (int i = 0; i < 4; ++i) {
    const glm::vec3 at(-4.0f + 2.7f * i, 0.8f, 1.0f - 4.0f * i);
    scene.addShape(Shape::Box, glm::scale(glm::translate(glm::mat4(1.0f), at), glm::vec3(0.8f, 1.6f, 0.8f)), {});
  }
  RandomLightSpec spec;
  spec.count = 3000;
  spec.seed = 41;
  spec.boundsMin = {-12.0f, -1.0f, -30.0f};
  spec.boundsMax = {12.0f, 5.0f, 8.0f};
  spec.radiusMin = 0.5f;
  spec.radiusMax = 4.0f;
  spec.powerMin = 0.5f;
  spec.powerMax = 5.0f;
  scene.lights = makeRandomLights(spec);
  return scene;
}

struct Assigned {
  std::vector<std::vector<uint32_t>> lists;
  LightStats stats;
  uint32_t windowLights = 0;
};

Assigned assign(const Scene& scene, const ClusterConfig& config) {
  const ShaderLibrary shaders;
  Renderer renderer(shaders, scene, kWidth, kHeight, RendererConfig{config});
  Profiler profiler(TimingMode::Serializing);
  renderer.renderFrame({}, profiler);
  renderer.renderFrame({}, profiler);
  return {renderer.clusters().readLists(), renderer.lightStats(), renderer.clusters().windowLights()};
}

}  // namespace

TEST_CASE("clusters: masks over their budget are built in windows of lights, with the lists of one window") {
  PBR_REQUIRE_GL();
  const Scene scene = windowScene();
  const Assigned whole = assign(scene, ClusterConfig{});
  REQUIRE(whole.windowLights == scene.lights.size());
  const uint32_t active = whole.stats.activeClusters;
  REQUIRE(active > 100);
  REQUIRE(whole.stats.indexEntries > 10000);

  // 200 bytes per active cluster: the 3,000-light masks (388 bytes a slot) do not fit, 1,024-light ones do.
  ClusterConfig budget;
  budget.maxMaskBytes = 200ull * active;
  const Assigned windowed = assign(scene, budget);
  CHECK(windowed.windowLights < scene.lights.size());
  CHECK(windowed.windowLights % 1024 == 0);
  CHECK(windowed.stats.overflowedClusters == 0);
  CHECK(windowed.stats.activeClusters == active);
  CHECK(windowed.stats.indexEntries == whole.stats.indexEntries);
  REQUIRE(windowed.lists.size() == whole.lists.size());
  size_t differing = 0;
  for (size_t c = 0; c < whole.lists.size(); ++c) differing += windowed.lists[c] != whole.lists[c] ? 1 : 0;
  CHECK(differing == 0);

  // And the windowed frame equals brute force.
  FrameOptions options;
  options.culling = Culling::None;
  const test::RenderedFrame reference = test::renderScene(scene, {kWidth, kHeight}, options, 1);
  options.culling = Culling::Clustered;
  const test::RenderedFrame frame = test::renderScene(scene, {kWidth, kHeight}, options, 2, budget);
  CHECK(frame.stats.overflowedClusters == 0);
  CHECK(test::maxRelativeDifference(frame.hdr, reference.hdr) <= 1e-5);
  CHECK(test::countDifferentBytes(frame.ldr, reference.ldr) == 0);
}

TEST_CASE("clusters: clusters past the masks' slots are shaded by brute force, equal to brute force") {
  PBR_REQUIRE_GL();
  const Scene scene = windowScene();
  FrameOptions options;
  options.culling = Culling::None;
  const test::RenderedFrame reference = test::renderScene(scene, {kWidth, kHeight}, options, 1);
  options.culling = Culling::Clustered;
  const test::RenderedFrame whole = test::renderScene(scene, {kWidth, kHeight}, options, 2);
  // 20 bytes per active cluster: a tenth of the slots even for 1,024-light windows (132 bytes a slot).
  ClusterConfig budget;
  budget.maxMaskBytes = 20ull * whole.stats.activeClusters;
  const test::RenderedFrame starved = test::renderScene(scene, {kWidth, kHeight}, options, 2, budget);
  CHECK(starved.stats.activeClusters == whole.stats.activeClusters);
  CHECK(starved.stats.overflowedClusters > whole.stats.activeClusters / 2);
  CHECK(test::maxRelativeDifference(starved.hdr, reference.hdr) <= 1e-5);
  CHECK(test::countDifferentBytes(starved.ldr, reference.ldr) == 0);
  CHECK(test::countDifferentBytes(starved.ldr, whole.ldr) == 0);
}
