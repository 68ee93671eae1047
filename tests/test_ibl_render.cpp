// Image-based lighting through the whole renderer: the environment of a Scene, precomputed by the Renderer,
// lighting the G-buffer in the deferred pass next to the clustered point lights and shown behind the geometry.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "renderer/renderer.hpp"
#include "core/scene/assets.hpp"
#include "core/scene/builtin_scenes.hpp"
#include "tests/cli_util.hpp"
#include "tests/gl_test_context.hpp"
#include "tests/render_util.hpp"

using namespace pbr;
using test::PbrRun;
using test::TempDir;

namespace {

glm::vec3 pixel(const ImageRgbaF& image, int x, int y) {
  const size_t i = 4 * (static_cast<size_t>(y) * image.width + x);
  return {image.pixels[i], image.pixels[i + 1], image.pixels[i + 2]};
}

float maxRelative(const glm::vec3& got, const glm::vec3& want) {
  const glm::vec3 d = glm::abs(got - want) / glm::max(glm::abs(want), glm::vec3(1e-6f));
  return std::max(d.x, std::max(d.y, d.z));
}

SkyParams uniformSky(float radiance) {
  SkyParams sky;
  sky.zenith = sky.horizon = sky.ground = glm::vec3(radiance);
  sky.sunRadiance = glm::vec3(0.0f);
  return sky;
}

// A white Lambert-like sphere of radius 1 at the origin, seen head-on from z = 4 (fov 40: the disc's radius is
// 0.71 of half the frame's height).
Scene furnaceScene() {
  Scene s;
  s.name = "ibl-furnace";
  s.camera.position = {0.0f, 0.0f, 4.0f};
  s.camera.target = {0.0f, 0.0f, 0.0f};
  s.camera.fovYDeg = 40.0f;
  Material white;
  white.baseColor = glm::vec3(1.0f);
  white.roughness = 1.0f;
  white.metalness = 0.0f;
  s.addShape(Shape::Sphere, glm::scale(glm::mat4(1.0f), glm::vec3(2.0f)), white);
  s.environment = EnvironmentDesc{};
  s.environment->sky = uniformSky(1.0f);
  return s;
}

// A floor and two spheres (rough dielectric, smooth metal) under the default sky, with point lights near them.
Scene mixedScene(int lights) {
  Scene s;
  s.name = "ibl-mixed";
  s.camera.position = {0.0f, 2.0f, 6.0f};
  s.camera.target = {0.0f, 0.5f, 0.0f};
  s.camera.nearPlane = 0.3f;
  s.addShape(Shape::Plane, glm::scale(glm::mat4(1.0f), glm::vec3(8.0f, 1.0f, 8.0f)), {glm::vec3(0.6f), 0.7f, 0.0f});
  s.addShape(Shape::Sphere, glm::translate(glm::mat4(1.0f), glm::vec3(-1.0f, 0.6f, 0.0f)),
             {glm::vec3(0.8f, 0.3f, 0.2f), 0.6f, 0.0f});
  s.addShape(Shape::Sphere, glm::translate(glm::mat4(1.0f), glm::vec3(1.0f, 0.6f, 0.0f)),
             {glm::vec3(0.9f, 0.8f, 0.5f), 0.2f, 1.0f});
  RandomLightSpec spec;
  spec.count = lights;
  spec.seed = 3;
  spec.boundsMin = {-3.0f, 0.1f, -3.0f};
  spec.boundsMax = {3.0f, 2.0f, 3.0f};
  spec.radiusMin = 1.0f;
  spec.radiusMax = 3.0f;
  spec.powerMin = 20.0f;
  spec.powerMax = 80.0f;
  s.lights = makeRandomLights(spec);
  s.environment = EnvironmentDesc{};
  s.environment->sky.sunRadiance = glm::vec3(2000.0f);
  s.environment->sky.sunAngularRadiusDeg = 2.0f;
  return s;
}

FrameOptions pbrOptions(Culling culling = Culling::Clustered) {
  FrameOptions o;
  o.culling = culling;
  return o;
}

}  // namespace

TEST_CASE("ibl render: a white sphere in a uniform environment of radiance 1 reflects 1, the background is 1") {
  PBR_REQUIRE_GL();
  const Scene scene = furnaceScene();
  const ShaderLibrary shaders;
  const int size = 48;
  Profiler precompute(TimingMode::Serializing);
  RendererConfig config;
  config.precomputeProfiler = &precompute;
  Renderer renderer(shaders, scene, size, size, config);
  const std::vector<FrameTiming> timings = precompute.takeResults(true);
  REQUIRE(timings.size() == 1);
  for (const char* pass : {"ibl environment", "ibl irradiance", "ibl specular", "ibl dfg"}) {
    CAPTURE(pass);
    CHECK(timings[0].pass(pass) > 0.0);
  }

  Profiler profiler(TimingMode::Serializing);
  ImageRgbaF pbrFrame, blinnFrame;
  renderer.renderFrame(pbrOptions(), profiler, {nullptr, &pbrFrame});
  FrameOptions blinn = pbrOptions();
  blinn.model = ShadingModel::BlinnPhong;
  renderer.renderFrame(blinn, profiler, {nullptr, &blinnFrame});

  // The disc's radius is tan(asin(1/4)) / tan(20 deg) of half the frame, about 17 pixels; stay well inside it.
  const float c = 0.5f * (size - 1);
  float worst = 0.0f;
  int interior = 0;
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      if (std::hypot(x - c, y - c) > 12.0f) continue;
      worst = std::max(worst, maxRelative(pixel(pbrFrame, x, y), glm::vec3(1.0f)));
      CHECK(maxRelative(pixel(blinnFrame, x, y), glm::vec3(0.02f)) < 1e-2f);  // Blinn-Phong keeps its ambient
      ++interior;
    }
  }
  CHECK(interior > 400);
  CHECK(worst < 0.02f);
  MESSAGE("white furnace through the renderer: worst interior pixel " << worst * 100.0f << "% off 1");
  // Corners see no geometry: the environment for PBR, black for Blinn-Phong.
  CHECK(maxRelative(pixel(pbrFrame, 0, 0), glm::vec3(1.0f)) < 1e-3f);
  CHECK(pixel(blinnFrame, 0, 0) == glm::vec3(0.0f));
}

TEST_CASE("ibl render: background pixels follow the sky gradient from the horizon to the zenith and the ground") {
  PBR_REQUIRE_GL();
  Scene scene;
  scene.name = "ibl-sky";
  scene.camera.position = {0.0f, 0.0f, 0.0f};
  scene.camera.target = {0.0f, 0.0f, -1.0f};
  scene.camera.fovYDeg = 90.0f;
  SkyParams sky;
  sky.zenith = {0.1f, 0.2f, 0.8f};
  sky.horizon = {0.9f, 0.8f, 0.6f};
  sky.ground = {0.3f, 0.2f, 0.1f};
  sky.sunRadiance = glm::vec3(0.0f);
  scene.environment = EnvironmentDesc{};
  scene.environment->sky = sky;
  const int size = 33;  // odd: the middle row and column look exactly along the axes
  const test::RenderedFrame level = test::renderScene(scene, {size, size}, pbrOptions(), 1);

  // The top and bottom rows look about 44 degrees above and below the horizon.
  const float elevation = std::atan((size - 0.5f) / size * 2.0f - 1.0f);
  const float t = std::sqrt(std::sin(elevation));
  const glm::vec3 up = pixel(level.hdr, size / 2, 0), down = pixel(level.hdr, size / 2, size - 1);
  const glm::vec3 horizon = pixel(level.hdr, size / 2, size / 2);
  CHECK(maxRelative(up, glm::mix(sky.horizon, sky.zenith, t)) < 0.03f);
  CHECK(maxRelative(down, glm::mix(sky.horizon, sky.ground, t)) < 0.03f);
  // At the horizon the cube's texels straddle it, each a little way up or down the steep sqrt ramp.
  CHECK(glm::length(horizon - sky.horizon) < 0.2f * glm::length(sky.horizon - sky.zenith));

  scene.camera.target = {0.0f, 1.0f, 0.0f};
  scene.camera.up = {0.0f, 0.0f, -1.0f};
  const test::RenderedFrame zenith = test::renderScene(scene, {size, size}, pbrOptions(), 1);
  CHECK(maxRelative(pixel(zenith.hdr, size / 2, size / 2), sky.zenith) < 0.01f);
}

TEST_CASE("ibl render: environment and point lights add up, clustered equals brute force with an environment") {
  PBR_REQUIRE_GL();
  const glm::ivec2 size{96, 54};
  const Scene both = mixedScene(64);
  Scene environmentOnly = both;
  environmentOnly.lights.clear();
  Scene lightsOnly = both;
  lightsOnly.environment.reset();

  const test::RenderedFrame a = test::renderScene(environmentOnly, size, pbrOptions(), 1);
  const test::RenderedFrame b = test::renderScene(lightsOnly, size, pbrOptions(), 2);
  const test::RenderedFrame sum = test::renderScene(both, size, pbrOptions(), 2);
  const test::RenderedFrame brute = test::renderScene(both, size, pbrOptions(Culling::None), 1);

  // Each frame is rounded to fp16 once: 2^-11 relative per value, three values.
  double worst = 0.0;
  for (size_t i = 0; i < sum.hdr.pixels.size(); ++i) {
    if (i % 4 == 3) continue;
    const double expected = double(a.hdr.pixels[i]) + double(b.hdr.pixels[i]);
    const double magnitude = std::abs(double(a.hdr.pixels[i])) + std::abs(double(b.hdr.pixels[i]));
    const double tolerance = 3.0 * std::ldexp(1.0, -11) * magnitude + 1e-6;
    worst = std::max(worst, std::abs(double(sum.hdr.pixels[i]) - expected) / tolerance);
  }
  CHECK(worst <= 1.0);
  CHECK(sum.stats.overflowedClusters == 0);
  CHECK(sum.hdr.pixels == brute.hdr.pixels);
  CHECK(test::countDifferentBytes(sum.ldr, brute.ldr) == 0);
}

TEST_CASE("ibl render: pbr render --environment with a shipped .hdr, the sky, and a bad .hdr from a scene file") {
  const TempDir dir;
  const std::string hdr = assetPath("environments/venice_sunset_1k.hdr");
  const std::string png = dir.file("env.png");
  const PbrRun run = test::runPbr(dir, {"render", "--scene", "sphere-grid", "--size", "64x36", "--environment", hdr,
                                        "--environment-intensity", "0.5", "--out", png});
  CAPTURE(run.err);
  CHECK(run.exitCode == 0);
  CHECK(run.out.find("environment: " + hdr) != std::string::npos);
  CHECK(run.out.find("ibl specular") != std::string::npos);
  CHECK(std::filesystem::file_size(png) > 0);

  const PbrRun usage = test::runPbr(dir, {"render", "--size", "64x36", "--environment-intensity", "2"});
  CHECK(usage.exitCode == 2);
  CHECK(test::isOneLine(usage.err));

  const std::string bad = dir.write("bad.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 4 +X 4\n");
  const std::string sceneFile = dir.write(
      "bad.json", R"({"camera": {"position": [0, 0, 5], "target": [0, 0, 0]}, "environment": {"file": "bad.hdr"}})");
  const PbrRun broken = test::runPbr(dir, {"render", "--scene", sceneFile, "--size", "64x36"});
  CAPTURE(broken.err);
  CHECK(broken.exitCode == 1);
  CHECK(test::isOneLine(broken.err));
  CHECK(broken.err.find(bad + ": truncated Radiance file") != std::string::npos);
}
