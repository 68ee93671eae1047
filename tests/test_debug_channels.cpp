// The debug channels of `pbr render --debug` and the viewer: each shows the expected channel, checked against
// values worked out here from the scenes' definitions (sphere-grid's rows and columns, a floor's distance along
// each pixel's ray, a material's factors), and each channel with a scale carries a legend bar of that scale.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include "core/scene/builtin_scenes.hpp"
#include "core/scene/gltf_loader.hpp"
#include "renderer/renderer.hpp"
#include "tests/cli_util.hpp"
#include "tests/gl_test_context.hpp"
#include "tests/gltf_builder.hpp"
#include "tests/render_util.hpp"

using pbr::DebugChannel;
using json = nlohmann::json;

namespace {

// 4:3 keeps sphere-grid's bottom row above the legend in the bottom-left corner; under 360 rows the legend's font
// pixels are one image pixel each.
const glm::ivec2 kSize{320, 240};

pbr::FrameOptions channel(DebugChannel c, pbr::Culling culling = pbr::Culling::Clustered) {
  pbr::FrameOptions options;
  options.culling = culling;
  options.debug = c;
  options.aa = pbr::AntiAliasing::Fxaa;  // as pbr render: a channel that replaces the frame is never filtered
  return options;
}

glm::ivec3 rgbAt(const pbr::ImageRgba8& image, glm::ivec2 p) {
  const uint8_t* q = &image.pixels[(static_cast<size_t>(p.y) * image.width + p.x) * 4];
  return {q[0], q[1], q[2]};
}

// The pixel (rows top-down) whose centre is nearest the projection of `world`, from the camera's definition.
glm::ivec2 pixelOf(const pbr::Camera& camera, glm::vec3 world) {
  const glm::mat4 view = glm::lookAt(camera.position, camera.target, camera.up);
  const glm::vec3 v = glm::vec3(view * glm::vec4(world, 1.0f));
  const float t = std::tan(glm::radians(camera.fovYDeg) / 2.0f);
  const float aspect = float(kSize.x) / float(kSize.y);
  const glm::vec2 ndc(v.x / (-v.z * t * aspect), v.y / (-v.z * t));
  return {int(std::floor((ndc.x * 0.5f + 0.5f) * kSize.x)), int(std::floor((0.5f - ndc.y * 0.5f) * kSize.y))};
}

// The direction through the centre of pixel p (rows top-down), scaled to a component of 1 along the view axis: a
// point at distance s along it lies at view depth s.
glm::dvec3 rayThrough(const pbr::Camera& camera, glm::ivec2 p) {
  const glm::dvec3 f = glm::normalize(glm::dvec3(camera.target - camera.position));
  const glm::dvec3 r = glm::normalize(glm::cross(f, glm::dvec3(camera.up)));
  const glm::dvec3 u = glm::cross(r, f);
  const double t = std::tan(glm::radians(double(camera.fovYDeg)) / 2.0), aspect = double(kSize.x) / kSize.y;
  const double ndcX = (p.x + 0.5) / kSize.x * 2.0 - 1.0, ndcY = 1.0 - (p.y + 0.5) / kSize.y * 2.0;
  return f + ndcX * t * aspect * r + ndcY * t * u;
}

// The legend lies in the bottom-left corner: its panel is at most 30 font pixels tall.
bool inLegendCorner(glm::ivec2 p) {
  const int scale = std::max(1, kSize.y / 180);
  return p.y >= kSize.y - 32 * scale && p.x < kSize.x * 3 / 4;
}

int byteOf(double v) { return int(std::lround(std::clamp(v, 0.0, 1.0) * 255.0)); }

double srgbEncode(double c) { return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055; }

// The heat ramp the legend documents (black, blue, cyan, green, yellow, red at t = 0, 0.2, ..., 1) inverted: the t
// of the ramp colour nearest `rgb`, or nothing when no ramp colour is within a few 8-bit levels.
std::optional<double> heatValue(glm::ivec3 rgb) {
  static const glm::dvec3 stops[6] = {{0.0, 0.0, 0.0}, {0.0, 0.1, 0.9}, {0.0, 0.8, 0.9},
                                      {0.1, 0.85, 0.1}, {1.0, 0.9, 0.0}, {1.0, 0.05, 0.0}};
  const glm::dvec3 c = glm::dvec3(rgb) / 255.0;
  double best = 1e9, bestT = 0.0;
  for (int i = 0; i < 5; ++i) {
    const glm::dvec3 d = stops[i + 1] - stops[i];
    const double s = std::clamp(glm::dot(c - stops[i], d) / glm::dot(d, d), 0.0, 1.0);
    const double distance = glm::length(c - (stops[i] + s * d));
    if (distance < best) {
      best = distance;
      bestT = (i + s) / 5.0;
    }
  }
  if (best > 4.0 / 255.0) return std::nullopt;
  return bestT;
}

// The no-data pattern: grey checks of 0.3 and 0.18, which no ramp colour matches.
bool isNoData(glm::ivec3 rgb) {
  return rgb.x == rgb.y && rgb.y == rgb.z && (std::abs(rgb.x - 77) <= 1 || std::abs(rgb.x - 46) <= 1);
}

// Somewhere in the legend corner a row runs through `decode`'s scale from below 0.05 to above 0.95, never going
// back by more than two 8-bit levels, over at least 80 pixels: the legend's bar. And the legend has white text.
template <class Decode>
void checkLegendBar(const pbr::ImageRgba8& image, Decode decode) {
  bool bar = false, text = false;
  for (int y = kSize.y - 32; y < kSize.y && !bar; ++y) {
    int run = 0;
    double first = 0.0, last = -1.0;
    for (int x = 0; x < kSize.x && !bar; ++x) {
      const std::optional<double> v = decode(rgbAt(image, {x, y}));
      if (v && (run == 0 || *v >= last - 2.0 / 255.0)) {
        if (run++ == 0) first = *v;
        last = *v;
        bar = run >= 80 && first < 0.05 && last > 0.95;
      } else {
        run = 0;
      }
    }
  }
  for (int y = kSize.y - 32; y < kSize.y; ++y) {
    for (int x = 0; x < kSize.x / 2; ++x) text |= rgbAt(image, {x, y}) == glm::ivec3(255);
  }
  CHECK(bar);
  CHECK(text);
}

std::optional<double> grey(glm::ivec3 rgb) {
  if (rgb.x != rgb.y || rgb.y != rgb.z) return std::nullopt;
  return rgb.x / 255.0;
}

// sphere-grid (scenes/sphere-grid.json): sphere (i, j) at (-3.6 + 1.2 i, -3.6 + 1.2 j, 0), metalness i / 6 and
// roughness j / 6, base colour (1, 0.71, 0.29); the camera at (0, 0, 13) looks down -Z.
glm::vec3 gridSphere(int i, int j) { return {-3.6f + 1.2f * i, -3.6f + 1.2f * j, 0.0f}; }

// A floor under 64 random lights and a sphere on it, seen from above so that the floor keeps clear of the legend;
// both coloured, so that the legend's grey panel tells from them.
pbr::Scene floorScene() {
  pbr::Scene scene;
  scene.camera.position = {0.0f, 9.0f, 6.0f};
  scene.camera.target = {0.0f, 0.0f, 0.5f};
  scene.camera.fovYDeg = 45.0f;
  scene.camera.nearPlane = 0.5f;
  scene.camera.farPlane = 40.0f;
  pbr::Material floor;
  floor.baseColor = {0.45f, 0.3f, 0.2f};
  floor.roughness = 0.75f;
  pbr::Material ball;
  ball.baseColor = {0.2f, 0.5f, 0.8f};
  scene.addShape(pbr::Shape::Plane, glm::scale(glm::mat4(1.0f), glm::vec3(6.0f, 1.0f, 6.0f)), floor);
  scene.addShape(pbr::Shape::Sphere, glm::scale(glm::translate(glm::mat4(1.0f), {0.0f, 1.0f, 0.0f}), glm::vec3(2.0f)),
                 ball);
  pbr::RandomLightSpec lights;
  lights.count = 64;
  lights.boundsMin = {-3.0f, 0.2f, -3.0f};
  lights.boundsMax = {3.0f, 1.5f, 3.0f};
  lights.radiusMin = 0.8f;
  lights.radiusMax = 2.0f;
  scene.lights = pbr::makeRandomLights(lights);
  return scene;
}

}  // namespace

TEST_CASE("debug channels: sphere-grid's roughness rises up the grid and its metalness to the right") {
  PBR_REQUIRE_GL();
  const pbr::Scene scene = pbr::makeBuiltinScene("sphere-grid");
  const pbr::test::RenderedFrame roughness = pbr::test::renderScene(scene, kSize, channel(DebugChannel::Roughness));
  const pbr::test::RenderedFrame metalness = pbr::test::renderScene(scene, kSize, channel(DebugChannel::Metalness));
  for (int i = 0; i < 7; ++i) {
    for (int j = 0; j < 7; ++j) {
      CAPTURE(i);
      CAPTURE(j);
      const glm::ivec2 p = pixelOf(scene.camera, gridSphere(i, j));
      REQUIRE_FALSE(inLegendCorner(p));
      CHECK(std::abs(rgbAt(roughness.ldr, p).x - byteOf(j / 6.0)) <= 1);
      CHECK(std::abs(rgbAt(metalness.ldr, p).x - byteOf(i / 6.0)) <= 1);
      CHECK(grey(rgbAt(roughness.ldr, p)).has_value());
      CHECK(grey(rgbAt(metalness.ldr, p)).has_value());
    }
  }
  CHECK(rgbAt(roughness.ldr, {2, 2}) == glm::ivec3(0));  // no surface: black
  checkLegendBar(roughness.ldr, grey);
  checkLegendBar(metalness.ldr, grey);
}

TEST_CASE("debug channels: base colour is the material's factor sRGB-encoded, normals are world-space") {
  PBR_REQUIRE_GL();
  const pbr::Scene grid = pbr::makeBuiltinScene("sphere-grid");
  const pbr::test::RenderedFrame base = pbr::test::renderScene(grid, kSize, channel(DebugChannel::BaseColor));
  const glm::dvec3 factor(1.0, 0.71, 0.29);
  for (int i = 0; i < 7; i += 3) {
    const glm::ivec3 got = rgbAt(base.ldr, pixelOf(grid.camera, gridSphere(i, 3)));
    for (int c = 0; c < 3; ++c) CHECK(std::abs(got[c] - byteOf(srgbEncode(factor[c]))) <= 1);
  }

  // The ray through the centre of the pixel at a sphere's projected centre meets the sphere (radius 0.5) where its
  // normal is (hit - centre) / 0.5.
  const pbr::test::RenderedFrame normal = pbr::test::renderScene(grid, kSize, channel(DebugChannel::Normal));
  const auto decoded = [&](const pbr::ImageRgba8& image, glm::ivec2 p) {
    return glm::dvec3(rgbAt(image, p)) / 255.0 * 2.0 - 1.0;
  };
  for (const glm::ivec2 ij : {glm::ivec2(3, 3), glm::ivec2(6, 3), glm::ivec2(0, 6)}) {
    const glm::dvec3 centre = gridSphere(ij.x, ij.y);
    const glm::ivec2 p = pixelOf(grid.camera, centre);
    const glm::dvec3 eye = grid.camera.position, d = glm::normalize(rayThrough(grid.camera, p));
    const glm::dvec3 oc = eye - centre;
    const double b = glm::dot(oc, d), c = glm::dot(oc, oc) - 0.25;
    const glm::dvec3 want = (eye + (-b - std::sqrt(b * b - c)) * d - centre) / 0.5;
    CAPTURE(ij.x);
    CAPTURE(ij.y);
    CHECK(glm::length(decoded(normal.ldr, p) - want) < 0.02);
  }
  // World space, not view space: the default scene's camera looks down at its floor, whose normal stays +Y.
  const pbr::Scene tilted = pbr::makeBuiltinScene("default");
  const pbr::test::RenderedFrame floor = pbr::test::renderScene(tilted, kSize, channel(DebugChannel::Normal));
  CHECK(glm::length(decoded(floor.ldr, {kSize.x - 8, kSize.y - 8}) - glm::dvec3(0.0, 1.0, 0.0)) < 0.02);
}

TEST_CASE("debug channels: depth is the view depth along each pixel's ray, log scale from near to far") {
  PBR_REQUIRE_GL();
  pbr::Scene scene;
  scene.camera.position = {0.0f, 3.0f, 6.0f};
  scene.camera.target = {0.0f, 0.0f, 0.0f};
  scene.camera.fovYDeg = 45.0f;
  scene.camera.nearPlane = 0.5f;
  scene.camera.farPlane = 40.0f;
  scene.addShape(pbr::Shape::Plane, glm::scale(glm::mat4(1.0f), glm::vec3(100.0f, 1.0f, 100.0f)), pbr::Material{});
  const pbr::test::RenderedFrame depth = pbr::test::renderScene(scene, kSize, channel(DebugChannel::Depth));
  // The ray through a pixel's centre meets the floor y = 0 at view depth s: -camera height / ray.y.
  const double near = 0.5, far = 40.0;
  int checked = 0;
  double previous = 0.0;
  const int x = kSize.x - 30;  // right of the legend
  for (int y = kSize.y - 1; y >= 0; --y) {
    const glm::dvec3 ray = rayThrough(scene.camera, {x, y});
    const double want = ray.y < 0.0 ? -scene.camera.position.y / ray.y : 1e9;
    const int shown = rgbAt(depth.ldr, {x, y}).x;
    if (want > 0.9 * far) continue;
    const double got = near * std::pow(far / near, 1.0 - shown / 255.0);
    CAPTURE(y);
    CHECK(got == doctest::Approx(want).epsilon(0.025));
    CHECK(got >= previous);  // farther up the image
    previous = got;
    ++checked;
  }
  CHECK(checked > 80);
  checkLegendBar(depth.ldr, [](glm::ivec3 rgb) {
    const std::optional<double> v = grey(rgb);
    return v ? std::optional<double>(1.0 - *v) : std::nullopt;
  });
}

TEST_CASE("debug channels: occlusion is the material's map and 1 without one") {
  PBR_REQUIRE_GL();
  const pbr::Scene grid = pbr::makeBuiltinScene("sphere-grid");
  const pbr::test::RenderedFrame shapes = pbr::test::renderScene(grid, kSize, channel(DebugChannel::Occlusion));
  for (int i = 0; i < 7; i += 2) CHECK(rgbAt(shapes.ldr, pixelOf(grid.camera, gridSphere(i, 2 + i / 2))).x == 255);

  // A quad whose occlusion map holds 64 everywhere, at strength 0.5: occlusion 1 + 0.5 (64 / 255 - 1).
  const pbr::test::TempDir dir;
  pbr::test::GltfBuilder b;
  b.addPngTexture(dir.path(), "ao.png", pbr::test::solidImage(2, 2, {64, 64, 64, 255}));
  pbr::test::QuadSpec quad;
  quad.material = b.addMaterial({{"occlusionTexture", {{"index", 0}, {"strength", 0.5}}}});
  b.addRootNode({{"mesh", pbr::test::addQuad(b, quad)}});
  const std::string path = b.writeGltf(dir.path(), "occluded");
  pbr::Scene scene;
  scene.camera.position = {0.0f, 0.0f, 3.0f};
  scene.camera.target = {0.0f, 0.0f, 0.0f};
  pbr::appendGltf(scene, path);
  const pbr::test::RenderedFrame mapped = pbr::test::renderScene(scene, kSize, channel(DebugChannel::Occlusion));
  CHECK(std::abs(rgbAt(mapped.ldr, kSize / 2).x - byteOf(1.0 + 0.5 * (64.0 / 255.0 - 1.0))) <= 1);
  checkLegendBar(mapped.ldr, grey);
}

TEST_CASE("debug channels: emission shows the emitted radiance alone, where a material emits") {
  PBR_REQUIRE_GL();
  pbr::Scene scene;
  scene.camera.position = {0.0f, 0.0f, 6.0f};
  scene.camera.target = {0.0f, 0.0f, 0.0f};
  scene.ambient = glm::vec3(0.2f);
  pbr::Material glowing;
  glowing.emissive = glm::vec3(0.5f, 0.25f, 0.0f);
  const glm::vec3 left(-1.2f, 0.0f, 0.0f), right(1.2f, 0.0f, 0.0f);
  scene.addShape(pbr::Shape::Sphere, glm::translate(glm::mat4(1.0f), left), glowing);
  scene.addShape(pbr::Shape::Sphere, glm::translate(glm::mat4(1.0f), right), pbr::Material{});
  scene.lights.push_back({{0.0f, 1.0f, 3.0f}, 10.0f, glm::vec3(1.0f), 400.0f});
  // Blinn-Phong's post is a clamp and the sRGB encoding: the emitted radiance shows as sRGB(emission).
  pbr::FrameOptions options = channel(DebugChannel::Emission);
  options.model = pbr::ShadingModel::BlinnPhong;
  const pbr::test::RenderedFrame emission = pbr::test::renderScene(scene, kSize, options);
  options.debug.reset();
  const pbr::test::RenderedFrame lit = pbr::test::renderScene(scene, kSize, options);
  const glm::ivec2 l = pixelOf(scene.camera, left), r = pixelOf(scene.camera, right);
  const glm::ivec3 glow = rgbAt(emission.ldr, l);
  CHECK(std::abs(glow.x - byteOf(srgbEncode(0.5))) <= 1);
  CHECK(std::abs(glow.y - byteOf(srgbEncode(0.25))) <= 1);
  CHECK(glow.z == 0);
  CHECK(rgbAt(lit.ldr, r).x > 20);  // lit in the frame ...
  CHECK(rgbAt(emission.ldr, r) == glm::ivec3(0));  // ... but it emits nothing
  CHECK(rgbAt(emission.ldr, {kSize.x - 4, 4}) == glm::ivec3(0));
  // The radiance capture of the channel is the emitted radiance itself.
  const size_t at = (static_cast<size_t>(l.y) * kSize.x + l.x) * 4;
  CHECK(emission.hdr.pixels[at] == doctest::Approx(0.5f));
  CHECK(emission.hdr.pixels[at + 1] == doctest::Approx(0.25f));
}

TEST_CASE("debug channels: lights per cluster and depth slices paint the grid over the frame") {
  PBR_REQUIRE_GL();
  pbr::Scene scene = floorScene();
  const pbr::test::RenderedFrame clusters = pbr::test::renderScene(scene, kSize, channel(DebugChannel::Clusters));
  std::set<int> colours;
  for (int y = 60; y < 180; ++y) {
    const glm::ivec3 c = rgbAt(clusters.ldr, {kSize.x / 2 + 60, y});
    colours.insert((c.x << 16) | (c.y << 8) | c.z);
  }
  CHECK(colours.size() > 10);  // lights per cluster vary over the floor
  // The heat-map legend of the cluster view (its own colours are shaded by the frame, the bar's are not).
  checkLegendBar(clusters.ldr, heatValue);

  // Lit by ambient light alone the floor's shade barely changes, so the slice colours change where the slice of
  // the floor's view depth along each pixel's ray does: 192 slices, exponential between near and far.
  scene.lights.clear();
  scene.ambient = glm::vec3(0.5f);
  const pbr::test::RenderedFrame slices = pbr::test::renderScene(scene, kSize, channel(DebugChannel::Slices));
  const pbr::Camera& camera = scene.camera;
  const auto sliceAt = [&](int x, int y) {
    const double depth = -camera.position.y / rayThrough(camera, {x, y}).y;
    return 192.0 * std::log(depth / camera.nearPlane) / std::log(camera.farPlane / camera.nearPlane);
  };
  const int x = kSize.x / 2 + 60;
  int boundaries = 0, within = 0;
  for (int y = 60; y < 180; ++y) {
    const double a = sliceAt(x, y), b = sliceAt(x, y + 1);
    const glm::ivec3 d = glm::abs(rgbAt(slices.ldr, {x, y}) - rgbAt(slices.ldr, {x, y + 1}));
    const int change = std::max({d.x, d.y, d.z});
    CAPTURE(y);
    if (std::floor(a) != std::floor(b)) {
      CHECK(change > 12);
      ++boundaries;
    } else if (std::min(a, b) - std::floor(a) > 0.05 && std::ceil(a) - std::max(a, b) > 0.05) {
      CHECK(change <= 3);
      ++within;
    }
  }
  CHECK(boundaries > 5);
  CHECK(within > 40);
}

TEST_CASE("debug channels: culling efficiency per pixel, brute force below clustered, its mean the --stats figure") {
  PBR_REQUIRE_GL();
  const pbr::Scene scene = floorScene();
  pbr::FrameOptions brute = channel(DebugChannel::Efficiency, pbr::Culling::None);
  brute.stats = true;
  pbr::FrameOptions clustered = channel(DebugChannel::Efficiency, pbr::Culling::Clustered);
  clustered.stats = true;
  const pbr::test::RenderedFrame b = pbr::test::renderScene(scene, kSize, brute);
  const pbr::test::RenderedFrame c = pbr::test::renderScene(scene, kSize, clustered);
  // The final frame's surface pixels: the brute-force path evaluates every light at each of them.
  const pbr::test::RenderedFrame surface = pbr::test::renderScene(scene, kSize, channel(DebugChannel::BaseColor));
  double bruteSum = 0.0, clusteredSum = 0.0;
  int surfacePixels = 0, bothPairs = 0;
  for (int y = 0; y < kSize.y; ++y) {
    for (int x = 0; x < kSize.x; ++x) {
      const glm::ivec2 p{x, y};
      if (inLegendCorner(p)) {
        REQUIRE(grey(rgbAt(surface.ldr, p)).has_value());  // no (coloured) surface behind the legend
        continue;
      }
      const bool hasSurface = rgbAt(surface.ldr, p) != glm::ivec3(0);
      const std::optional<double> bt = heatValue(rgbAt(b.ldr, p)), ct = heatValue(rgbAt(c.ldr, p));
      CAPTURE(x);
      CAPTURE(y);
      // Brute force evaluates pairs exactly where there is a surface.
      REQUIRE(bool(bt) == hasSurface);
      REQUIRE(bool(bt) != isNoData(rgbAt(b.ldr, p)));
      if (!bt) continue;
      ++surfacePixels;
      bruteSum += *bt;
      // A cluster lists every light that contributes: where it lists none, no light contributes at all.
      if (!ct) {
        REQUIRE(isNoData(rgbAt(c.ldr, p)));
        CHECK(*bt < 0.01);
        continue;
      }
      ++bothPairs;
      clusteredSum += *ct;
      CHECK(*ct >= *bt - 0.01);
    }
  }
  REQUIRE(surfacePixels > 20000);
  const double bruteMean = bruteSum / surfacePixels;
  // Within 0.5 %: 8-bit colours decode to about 0.002 each, and their errors average out over the pixels.
  CHECK(bruteMean == doctest::Approx(b.stats.cullingEfficiency()).epsilon(0.005).scale(0.0));
  CHECK(clusteredSum / bothPairs > 2.0 * bruteMean);
  CHECK(b.stats.cullingEfficiency() < c.stats.cullingEfficiency());
  checkLegendBar(b.ldr, heatValue);
}

TEST_CASE("debug channels: pbr render --debug efficiency writes the heat map whose mean --stats prints") {
  PBR_REQUIRE_GL();
  const pbr::test::TempDir dir;
  const std::string scene = dir.write("floor.json", R"({
    "camera": {"position": [0, 9, 6], "target": [0, 0, 0.5], "fov_y_deg": 45, "near": 0.5, "far": 40},
    "objects": [{"shape": "plane", "transform": {"scale": [6, 1, 6]}}],
    "random_lights": {"count": 32, "bounds": [[-3, 0.2, -3], [3, 1.5, 3]], "radius": [0.8, 2],
                      "luminous_power": [20, 40]}})");
  const std::string png = dir.file("efficiency.png");
  const pbr::test::PbrRun run =
      pbr::test::runPbr(dir, {"render", "--scene", scene, "--size", "320x240", "--culling", "none", "--debug",
                              "efficiency", "--stats", "--frames", "1", "--warmup", "0", "--out", png});
  REQUIRE(run.exitCode == 0);
  std::smatch m;
  REQUIRE(std::regex_search(run.out, m, std::regex(R"(culling efficiency: ([0-9.]+))")));
  const double printed = std::stod(m[1]);
  const pbr::ImageRgba8 image = pbr::readPng(png);
  double sum = 0.0;
  int pixels = 0;
  for (int y = 0; y < kSize.y; ++y) {
    for (int x = 0; x < kSize.x; ++x) {
      const std::optional<double> t = heatValue(rgbAt(image, {x, y}));
      if (t && !inLegendCorner({x, y})) {
        sum += *t;
        ++pixels;
      }
    }
  }
  REQUIRE(pixels > 10000);
  CHECK(printed > 0.01);
  CHECK(std::abs(sum / pixels - printed) < 0.001);  // printed to 3 decimals
}
