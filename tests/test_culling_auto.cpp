#include <doctest/doctest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "core/scene/builtin_scenes.hpp"
#include "renderer/renderer.hpp"
#include "tests/gl_test_context.hpp"
#include "tests/render_util.hpp"

using namespace pbr;

// --culling auto (renderer/culling_choice.hpp): each frame runs the path its predictions, scaled from times
// measured here, say is cheaper. Asserted on the choice and on the predictions it reports, not on a time.
namespace {

constexpr int kWidth = 160, kHeight = 90;

Scene floorScene(int lights, float radiusMin, float radiusMax, uint64_t seed) {
  Scene s;
  s.camera.position = {0.0f, 3.0f, 6.0f};
  s.camera.target = {0.0f, 0.0f, 0.0f};
  s.camera.nearPlane = 0.3f;
  s.camera.farPlane = 40.0f;
  s.addShape(Shape::Plane, glm::scale(glm::mat4(1.0f), glm::vec3(60.0f, 1.0f, 60.0f)), {glm::vec3(0.6f), 0.7f, 0.0f});
  s.addShape(Shape::Sphere, glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 1.0f, 0.0f)),
             {glm::vec3(0.8f), 0.4f, 0.0f});
  RandomLightSpec spec;
  spec.count = lights;
  spec.seed = seed;
  spec.boundsMin = {-8.0f, 0.2f, -20.0f};
  spec.boundsMax = {8.0f, 3.0f, 4.0f};
  spec.radiusMin = radiusMin;
  spec.radiusMax = radiusMax;
  spec.powerMin = 100.0f / float(lights);
  spec.powerMax = 400.0f / float(lights);
  s.lights = makeRandomLights(spec);
  return s;
}

// Renders `frames` frames with culling auto, each compared with brute force; returns the last frame's statistics.
LightStats renderAuto(const Scene& scene, int frames) {
  FrameOptions options;
  options.culling = Culling::None;
  const test::RenderedFrame reference = test::renderScene(scene, {kWidth, kHeight}, options, 1);
  options.culling = Culling::Auto;
  const ShaderLibrary shaders;
  Renderer renderer(shaders, scene, kWidth, kHeight);
  Profiler profiler(TimingMode::Serializing);
  for (int frame = 0; frame < frames; ++frame) {
    ImageRgbaF hdr;
    renderer.renderFrame(options, profiler, FrameCapture{nullptr, &hdr});
    CAPTURE(frame);
    CHECK(test::maxRelativeDifference(hdr, reference.hdr) == 0.0);  // whichever path ran
  }
  return renderer.lightStats();
}

}  // namespace

TEST_CASE("culling auto: with every light reaching every pixel it times brute force and runs it") {
  PBR_REQUIRE_GL();
  // 256 lights each reaching the whole view: the lists hold every light, so clustering adds its passes and saves
  // no pair.
  // Enough frames for the measurements, the second timing of clustered 8 frames after them, and brute force again.
  const LightStats s = renderAuto(floorScene(256, 200.0f, 200.0f, 3), 24);
  REQUIRE(s.decision);
  CAPTURE(s.decision->describe());
  CHECK(s.decision->bruteForceMs > 0.0);
  CHECK(s.decision->clusteredMs > 0.0);
  CHECK(s.decision->bruteForceMs < s.decision->clusteredMs);
  CHECK((s.decision->ran == Culling::None));
  CHECK((s.culling == Culling::None));
  CHECK(s.activeClusters == 0);  // brute-force frames report no cluster figures
}

TEST_CASE("culling auto: with many small lights brute force is not even tried, and clustered runs") {
  PBR_REQUIRE_GL();
  const LightStats s = renderAuto(floorScene(4096, 0.2f, 0.8f, 5), 7);
  REQUIRE(s.decision);
  CAPTURE(s.decision->describe());
  CHECK((s.decision->ran == Culling::Clustered));
  CHECK((s.culling == Culling::Clustered));
  CHECK(s.decision->bruteForceMs < 0.0);  // never timed
  CHECK(s.decision->bruteForceAtLeastMs > s.decision->clusteredMs);
  CHECK(s.activeClusters > 0);
}

TEST_CASE("culling auto: a cluster debug view runs clustered, untimed") {
  PBR_REQUIRE_GL();
  const Scene scene = floorScene(48, 200.0f, 200.0f, 3);
  const ShaderLibrary shaders;
  Renderer renderer(shaders, scene, kWidth, kHeight);
  Profiler profiler(TimingMode::Serializing);
  FrameOptions options;
  options.culling = Culling::Auto;
  options.debug = DebugChannel::Clusters;
  for (int frame = 0; frame < 4; ++frame) renderer.renderFrame(options, profiler);
  const LightStats s = renderer.lightStats();
  CHECK((s.culling == Culling::Clustered));
  CHECK_FALSE(s.decision);
}
