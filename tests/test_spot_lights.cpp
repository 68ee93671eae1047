// Spot lights: a glTF spot aimed at a floor against the cone falloff of KHR_lights_punctual, evaluated here from
// the angles, and against the double-precision reference (clustered culling of cones: test_clusters.cpp).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "app/accuracy/accuracy_metrics.hpp"
#include "core/scene/scene_json.hpp"
#include "reference/reference_renderer.hpp"
#include "renderer/display_image.hpp"
#include "renderer/offscreen.hpp"
#include "tests/cli_util.hpp"
#include "tests/gl_test_context.hpp"
#include "tests/gltf_builder.hpp"

namespace ref = pbr::reference;
using pbr::test::TempDir;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kInner = 20.0 * kPi / 180.0, kOuter = 35.0 * kPi / 180.0;
constexpr double kLightHeight = 2.0, kEyeHeight = 5.0, kFovY = 45.0 * kPi / 180.0;

// A 20 x 20 floor (the quad, facing +Z, scaled), a spot light 2 above its centre shining straight at it (along the
// node's -Z) and a camera 5 above looking down at it, as an exporter writes them.
std::string writeSpotFloor(const TempDir& dir) {
  pbr::test::GltfBuilder b;
  const int material = b.addMaterial({{"pbrMetallicRoughness",
                                       {{"baseColorFactor", {0.8, 0.7, 0.6, 1.0}},
                                        {"metallicFactor", 0.0},
                                        {"roughnessFactor", 0.6}}}});
  pbr::test::QuadSpec quad;
  quad.material = material;
  b.addRootNode({{"mesh", pbr::test::addQuad(b, quad)}, {"scale", {10.0, 10.0, 1.0}}});
  b.doc["extensionsUsed"] = {"KHR_lights_punctual"};
  b.doc["extensions"]["KHR_lights_punctual"]["lights"] = {
      {{"type", "spot"},
       {"intensity", 5.0},
       {"range", 10.0},
       {"color", {1.0, 0.9, 0.8}},
       {"spot", {{"innerConeAngle", kInner}, {"outerConeAngle", kOuter}}}}};
  b.addRootNode({{"translation", {0.0, 0.0, kLightHeight}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
  b.doc["cameras"] = {{{"type", "perspective"},
                       {"perspective", {{"yfov", kFovY}, {"aspectRatio", 1.0}, {"znear", 0.1}, {"zfar", 50.0}}}}};
  b.addRootNode({{"translation", {0.0, 0.0, kEyeHeight}}, {"camera", 0}});
  return b.writeGltf(dir.path(), "spot-floor");
}

// The scene as loaded, lit by the spot light alone: no ambient light, no environment.
pbr::Scene spotAlone(const std::string& path) {
  pbr::Scene s = pbr::loadSceneFile(path);
  s.ambient = glm::vec3(0.0f);
  s.environment.reset();
  return s;
}

// glTF's angular falloff from the angles: clamp((cos - cos outer) / (cos inner - cos outer), 0, 1)^2.
double coneFalloff(double cosAngle) {
  const double x = std::clamp((cosAngle - std::cos(kOuter)) / (std::cos(kInner) - std::cos(kOuter)), 0.0, 1.0);
  return x * x;
}

}  // namespace

TEST_CASE("spot lights: a floor under a glTF spot is lit inside the cone, black outside, with glTF's falloff between") {
  PBR_REQUIRE_GL();
  const TempDir dir;
  const pbr::Scene spot = spotAlone(writeSpotFloor(dir));
  REQUIRE(spot.lights.size() == 1);
  REQUIRE(spot.lights[0].spot.has_value());
  pbr::Scene point = spot;
  point.lights[0].spot.reset();

  const pbr::ShaderLibrary shaders;
  const int n = 65;
  pbr::RendererConfig config;  // float G-buffer and target: only float arithmetic separates GPU and CPU
  config.gbuffer = pbr::GBufferPrecision::Float;
  config.hdrFormat = pbr::HdrFormat::Rgba32f;
  const pbr::FrameOptions options;
  const pbr::RenderedFrames lit = pbr::renderOffscreen(shaders, spot, {n, n}, options, 1, config);
  const pbr::RenderedFrames bare = pbr::renderOffscreen(shaders, point, {n, n}, options, 1, config);

  // The camera looks straight down the cone's axis: a pixel's floor point lies at r = 5 tan(fov/2) |ndc| from
  // the axis, and the light sees it at cos = 2 / sqrt(4 + r^2), whichever way the image is flipped.
  int inside = 0, between = 0, outside = 0;
  double worst = 0.0;
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < n; ++x) {
      const double ndcX = (x + 0.5) / n * 2.0 - 1.0, ndcY = (y + 0.5) / n * 2.0 - 1.0;
      const double r = kEyeHeight * std::tan(kFovY / 2.0) * std::hypot(ndcX, ndcY);
      const double cosAngle = kLightHeight / std::hypot(kLightHeight, r);
      const double falloff = coneFalloff(cosAngle);
      const float* s = lit.hdr.at(x, y);
      const float* p = bare.hdr.at(x, y);
      REQUIRE(p[1] > 0.0f);
      if (cosAngle < std::cos(kOuter) - 1e-3) {
        ++outside;
        CHECK(s[0] == 0.0f);
        CHECK(s[1] == 0.0f);
        CHECK(s[2] == 0.0f);
      } else {
        (cosAngle > std::cos(kInner) + 1e-3 ? inside : between) += 1;
        for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(double(s[c]) / p[c] - falloff));
      }
    }
  }
  CAPTURE(inside);
  CAPTURE(between);
  CAPTURE(outside);
  CHECK(inside > 100);
  CHECK(between > 100);
  CHECK(outside > 100);
  MESSAGE("largest difference of spot / point from the cone falloff: " << worst);
  CHECK(worst < 1e-3);

  // And the whole frame against the double-precision reference, which evaluates the cone on its own.
  pbr::FrameOptions exact;
  exact.variant = pbr::parseShadingVariant("fresnel=exact");
  const pbr::RenderedFrames gpu = pbr::renderOffscreen(shaders, spot, {n, n}, exact, 1, config);
  const ref::ReferenceFrame expected = ref::renderReference(spot, n, n);
  const pbr::ErrorMetrics e =
      pbr::measureError(gpu.hdr, gpu.ldr, expected, pbr::displayImage(shaders, expected.radiance, 1.0f));
  MESSAGE("relative RMSE against the reference: " << e.relativeRmse);
  CHECK(e.relativeRmse < 1e-3);
}
