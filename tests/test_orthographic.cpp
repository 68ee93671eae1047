// Orthographic cameras (glTF "orthographic", the JSON camera's "ortho_half_height"): where a glTF camera's view puts
// its quads as computed here from xmag and ymag, a lit scene against the reference's parallel rays, clustered
// against brute force, the environment behind a parallel view, and a scene file's camera.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "app/accuracy/accuracy_variants.hpp"
#include "core/scene/builtin_scenes.hpp"
#include "core/scene/model_scene.hpp"
#include "core/scene/scene_json.hpp"
#include "reference/reference_renderer.hpp"
#include "tests/cli_util.hpp"
#include "tests/cluster_test_scene.hpp"
#include "tests/gl_test_context.hpp"
#include "tests/gltf_builder.hpp"
#include "tests/refusal_checks.hpp"
#include "tests/render_util.hpp"

using nlohmann::json;
using pbr::test::GltfBuilder;
using pbr::test::QuadSpec;
using pbr::test::TempDir;

namespace {

// With a float G-buffer and radiance target, so that what differs from the reference is the renderer's arithmetic.
pbr::test::RenderedFrame renderFloat(const pbr::Scene& scene, glm::ivec2 size, const pbr::FrameOptions& options) {
  pbr::RendererConfig config;
  config.hdrFormat = pbr::HdrFormat::Rgba32f;
  config.gbuffer = pbr::GBufferPrecision::Float;
  const pbr::ShaderLibrary shaders;
  return pbr::renderOffscreen(shaders, scene, size, options, 2, config);
}

glm::vec3 rgb(const pbr::ImageRgbaF& image, int x, int y) {
  const float* v = image.at(x, y);
  return {v[0], v[1], v[2]};
}

pbr::Material material(const glm::vec3& base, float roughness, float metalness = 0.0f) {
  pbr::Material m;
  m.baseColor = base;
  m.roughness = roughness;
  m.metalness = metalness;
  return m;
}

// A rectangle of the image plane, in pixels from the top-left corner.
struct PixelRect {
  double x0, y0, x1, y1;
  // 1 for a pixel whose centre lies half a pixel or more inside, 0 half a pixel or more outside, -1 in between.
  int covers(int x, int y) const {
    const double cx = x + 0.5, cy = y + 0.5;
    const double inside = std::min({cx - x0, x1 - cx, cy - y0, y1 - cy});
    return inside >= 0.5 ? 1 : inside <= -0.5 ? 0 : -1;
  }
};

}  // namespace

TEST_CASE("orthographic: a glTF camera shows its quads where xmag and ymag put them, at any depth") {
  PBR_REQUIRE_GL();
  const TempDir dir;
  GltfBuilder b;
  const glm::vec3 red(0.9f, 0.1f, 0.1f), green(0.1f, 0.8f, 0.2f);
  const auto unlit = [&](const glm::vec3& c) {
    QuadSpec spec;
    spec.material = b.addMaterial({{"pbrMetallicRoughness", {{"baseColorFactor", {c.x, c.y, c.z, 1.0}}}},
                                   {"extensions", {{"KHR_materials_unlit", json::object()}}}});
    return pbr::test::addQuad(b, spec);
  };
  // Two 1 m squares (the builder's quad spans [-1, 1], halved), the green one 8 m farther from the camera.
  b.addRootNode({{"mesh", unlit(red)}, {"translation", {-1.5, 0.0, 0.0}}, {"scale", {0.5, 0.5, 0.5}}});
  b.addRootNode({{"mesh", unlit(green)}, {"translation", {1.5, 0.5, -8.0}}, {"scale", {0.5, 0.5, 0.5}}});
  b.doc["extensionsUsed"] = {"KHR_materials_unlit"};
  b.doc["cameras"] = {{{"type", "orthographic"},
                       {"orthographic", {{"xmag", 3.0}, {"ymag", 2.0}, {"znear", 0.0}, {"zfar", 20.0}}}}};
  b.doc["nodes"].push_back({{"translation", {0, 0, 10}}, {"camera", 0}});
  b.doc["scenes"][0]["nodes"] = {0, 1, 2};
  const pbr::Scene scene = pbr::loadModelScene(b.writeGltf(dir.path(), "ortho"));
  REQUIRE(scene.camera.orthographic);
  // znear 0 is valid; the near plane is put at 1e-4 of zfar, in a note.
  CHECK(scene.camera.nearPlane == doctest::Approx(0.002));
  CHECK(std::any_of(scene.notes.begin(), scene.notes.end(),
                    [](const std::string& n) { return n.find("orthographic.znear: 0") != std::string::npos; }));

  // 96 x 64 pixels show 6 m x 4 m: 16 pixels a metre, whatever the depth.
  const glm::ivec2 size{96, 64};
  const auto rect = [&](double cx, double cy) {
    const double s = 16.0;
    return PixelRect{48.0 + (cx - 0.5) * s, 32.0 - (cy + 0.5) * s, 48.0 + (cx + 0.5) * s, 32.0 - (cy - 0.5) * s};
  };
  const PixelRect near = rect(-1.5, 0.0), far = rect(1.5, 0.5);
  pbr::FrameOptions options;
  options.shadows.mode = pbr::ShadowMode::None;
  const pbr::test::RenderedFrame frame = renderFloat(scene, size, options);
  int redInside = 0, greenInside = 0, wrong = 0;
  for (int y = 0; y < size.y; ++y) {
    for (int x = 0; x < size.x; ++x) {
      const glm::vec3 c = rgb(frame.hdr, x, y);
      const int inRed = near.covers(x, y), inGreen = far.covers(x, y);
      if (inRed == 1) {
        redInside += 1;
        if (glm::any(glm::greaterThan(glm::abs(c - red), glm::vec3(1e-6f)))) ++wrong;
      } else if (inGreen == 1) {
        greenInside += 1;
        if (glm::any(glm::greaterThan(glm::abs(c - green), glm::vec3(1e-6f)))) ++wrong;
      } else if (inRed == 0 && inGreen == 0 && (c == red || c == green)) {
        ++wrong;
      }
    }
  }
  // Each square covers 16 x 16 whole pixels: its edges fall on pixel boundaries.
  CHECK(redInside == 256);
  CHECK(greenInside == 256);
  CHECK(wrong == 0);
}

TEST_CASE("orthographic: a lit scene seen along parallel rays matches the reference") {
  PBR_REQUIRE_GL();
  pbr::Scene scene;
  scene.camera.position = {4.0f, 5.0f, 7.0f};
  scene.camera.target = {0.0f, 0.6f, 0.0f};
  scene.camera.orthographic = true;
  scene.camera.orthoHalfHeight = 2.2f;
  scene.camera.nearPlane = 0.5f;
  scene.camera.farPlane = 30.0f;
  scene.ambient = glm::vec3(0.05f);
  scene.addShape(pbr::Shape::Plane, glm::scale(glm::mat4(1.0f), glm::vec3(20.0f)), material(glm::vec3(0.6f), 0.4f));
  scene.addShape(pbr::Shape::Sphere, glm::scale(glm::translate(glm::mat4(1.0f), {0.0f, 0.7f, -0.5f}), glm::vec3(1.4f)),
                 material({0.9f, 0.6f, 0.3f}, 0.3f, 1.0f));
  pbr::Material pane = material({0.2f, 0.5f, 1.0f}, 0.5f);
  pane.alpha = 0.4f;
  pane.alphaMode = pbr::AlphaMode::Blend;
  scene.addShape(pbr::Shape::Plane,
                 glm::scale(glm::rotate(glm::translate(glm::mat4(1.0f), {1.2f, 0.8f, 1.0f}), glm::radians(90.0f),
                                        {1.0f, 0.0f, 0.0f}),
                            {1.6f, 1.0f, 1.2f}),
                 pane);
  scene.directionalLights = {{glm::normalize(glm::vec3(0.5f, -0.8f, -0.3f)), glm::vec3(1.0f), 3.0f, false}};
  pbr::PointLight spot{{-2.0f, 2.5f, 2.0f}, 12.0f, glm::vec3(1.0f, 0.9f, 0.8f), 500.0f};
  spot.spot = pbr::SpotCone{glm::normalize(glm::vec3(0.6f, -0.7f, -0.5f)), 0.3f, 0.6f};
  scene.lights = {{{1.5f, 2.0f, 2.5f}, 10.0f, glm::vec3(0.7f, 0.8f, 1.0f), 300.0f}, spot};
  const auto ladder = pbr::accuracyLadder();
  const auto exact = std::find_if(ladder.begin(), ladder.end(), [](const auto& v) { return v.name == "exact-float"; });
  REQUIRE(exact != ladder.end());
  pbr::FrameOptions o;
  o.variant = exact->shading();
  o.shadows.mode = pbr::ShadowMode::None;
  const glm::ivec2 size{160, 96};
  const pbr::test::RenderedFrame gpu = renderFloat(scene, size, o);
  const pbr::reference::ReferenceFrame ref = pbr::reference::renderReference(scene, size.x, size.y, {});
  const double error = pbr::test::relativeRmse(gpu.hdr, ref.radiance);
  MESSAGE("relative RMSE against the reference: " << error);
  CHECK(error < 0.01);
  // The same camera in perspective, framing the target the same height, sees another image.
  pbr::Scene perspective = scene;
  perspective.camera.orthographic = false;
  const float distance = glm::distance(scene.camera.position, scene.camera.target);
  perspective.camera.fovYDeg = 2.0f * glm::degrees(std::atan(scene.camera.orthoHalfHeight / distance));
  CHECK(pbr::test::relativeRmse(renderFloat(perspective, size, o).hdr, ref.radiance) > 0.1);
}

TEST_CASE("orthographic: clustered frames equal brute force, and the clusters still cull") {
  PBR_REQUIRE_GL();
  pbr::Scene scene = pbr::test::clusterScene();
  scene.camera.orthographic = true;
  scene.camera.orthoHalfHeight = 4.0f;
  pbr::RandomLightSpec spec;
  spec.count = 1024;
  spec.seed = 17;
  spec.boundsMin = {-12.0f, 0.05f, -30.0f};
  spec.boundsMax = {12.0f, 4.0f, 8.0f};
  spec.radiusMin = 0.5f;
  spec.radiusMax = 3.0f;
  spec.powerMin = 2.0f;
  spec.powerMax = 40.0f;
  spec.spotShare = 0.5f;
  scene.lights = pbr::makeRandomLights(spec);
  // Lights straddling the near plane and behind the camera.
  const glm::vec3 forward = glm::normalize(scene.camera.target - scene.camera.position);
  scene.lights.push_back({scene.camera.position + forward * scene.camera.nearPlane + glm::vec3(1.0f, 0.0f, 0.0f), 2.0f,
                          {1.0f, 0.9f, 0.8f}, 30.0f});
  scene.lights.push_back({scene.camera.position - forward * 2.0f, 5.0f, {0.5f, 0.5f, 1.0f}, 60.0f});
  const glm::ivec2 size{160, 90};
  for (const pbr::ShadingModel model : {pbr::ShadingModel::Pbr, pbr::ShadingModel::BlinnPhong}) {
    CAPTURE(pbr::toString(model));
    pbr::FrameOptions o;
    o.model = model;
    o.culling = pbr::Culling::None;
    const pbr::test::RenderedFrame brute = pbr::test::renderScene(scene, size, o);
    o.culling = pbr::Culling::Clustered;
    const pbr::test::RenderedFrame clustered = pbr::test::renderScene(scene, size, o);
    CHECK(clustered.stats.overflowedClusters == 0);
    CHECK(clustered.hdr.pixels == brute.hdr.pixels);
    CHECK(pbr::test::countDifferentBytes(clustered.ldr, brute.ldr) == 0);
    // The lists hold a few of the lights, not all of them.
    MESSAGE("lights per non-empty cluster: " << clustered.stats.averagePerNonEmpty());
    CHECK(clustered.stats.averagePerNonEmpty() < 0.1 * double(scene.lights.size()));
  }
}

TEST_CASE("orthographic: a scene file's camera, and the environment behind a parallel view is one colour") {
  PBR_REQUIRE_GL();
  const TempDir dir;
  const auto write = [&](const json& camera) {
    return dir.write("ortho.json", json{{"camera", camera}, {"environment", {{"sky", json::object()}}}}.dump());
  };
  json camera = {{"position", {0, 1, 5}}, {"target", {0, 1.5, 0}}, {"ortho_half_height", 2.5}, {"far", 50}};
  const pbr::Scene scene = pbr::loadSceneFile(write(camera));
  REQUIRE(scene.camera.orthographic);
  CHECK(scene.camera.orthoHalfHeight == 2.5f);
  camera["fov_y_deg"] = 40;
  pbr::test::checkRefused(dir, write(camera), {"camera", "expected fov_y_deg or ortho_half_height, got both"});
  // Every pixel's ray has the view axis's direction: the sky shows one radiance, where a perspective view of the
  // same sky shows a gradient.
  const glm::ivec2 size{48, 32};
  const pbr::test::RenderedFrame ortho = pbr::test::renderScene(scene, size, {});
  const float* first = ortho.hdr.at(0, 0);
  int differing = 0;
  for (int y = 0; y < size.y; ++y) {
    for (int x = 0; x < size.x; ++x) differing += !std::equal(first, first + 3, ortho.hdr.at(x, y));
  }
  CHECK(differing == 0);
  CHECK(first[0] + first[1] + first[2] > 0.0f);
  pbr::Scene perspective = scene;
  perspective.camera.orthographic = false;
  const pbr::test::RenderedFrame persp = pbr::test::renderScene(perspective, size, {});
  CHECK(rgb(persp.hdr, 24, 0) != rgb(persp.hdr, 24, size.y - 1));
}

TEST_CASE("orthographic: sorted BLEND surfaces are drawn by their depth along the parallel view") {
  PBR_REQUIRE_GL();
  // Seen from the origin down -Z: a small red pane 5 m deep and a wide blue one 4.5 m deep, centred 6 m to the side,
  // overlapping the red one's part of the view. The blue one's centre is farther from the camera's position but
  // nearer its plane: back to front is red, then blue.
  pbr::Scene scene;
  scene.camera.position = {0.0f, 0.0f, 0.0f};
  scene.camera.target = {0.0f, 0.0f, -1.0f};
  scene.camera.orthographic = true;
  scene.camera.orthoHalfHeight = 2.0f;
  scene.camera.nearPlane = 0.5f;
  scene.camera.farPlane = 20.0f;
  scene.ambient = glm::vec3(0.5f);
  // The built-in plane is a unit square facing +Y, turned here to face the camera and scaled to `extent`.
  const auto pane = [](const glm::vec3& centre, const glm::vec2& extent) {
    return glm::scale(glm::rotate(glm::translate(glm::mat4(1.0f), centre), glm::radians(90.0f), {1.0f, 0.0f, 0.0f}),
                      {extent.x, 1.0f, extent.y});
  };
  scene.addShape(pbr::Shape::Plane, pane({0.0f, 0.0f, -8.0f}, {20.0f, 20.0f}), material(glm::vec3(0.5f), 0.8f));
  for (const auto& [centre, extent, colour] :
       {std::tuple{glm::vec3(0.0f, 0.0f, -5.0f), glm::vec2(2.0f), glm::vec3(1, 0, 0)},
        std::tuple{glm::vec3(6.0f, 0.0f, -4.5f), glm::vec2(14.0f, 2.0f), glm::vec3(0, 0, 1)}}) {
    pbr::Material m = material(colour, 0.8f);
    m.alpha = 0.5f;
    m.alphaMode = pbr::AlphaMode::Blend;
    scene.addShape(pbr::Shape::Plane, pane(centre, extent), m);
  }
  const glm::ivec2 size{64, 32};
  pbr::FrameOptions o;
  o.transparency = pbr::Transparency::Sorted;
  const pbr::test::RenderedFrame sorted = renderFloat(scene, size, o);
  o.transparency = pbr::Transparency::Exact;
  const pbr::test::RenderedFrame exact = renderFloat(scene, size, o);
  // Where both panes cover the view (x in [-1, 1] m: columns 24 to 39), sorting composites as the per-pixel lists do.
  for (int x = 26; x <= 37; x += 3) {
    CAPTURE(x);
    const glm::vec3 a = rgb(sorted.hdr, x, 16), b = rgb(exact.hdr, x, 16);
    for (int c = 0; c < 3; ++c) CHECK(a[c] == doctest::Approx(b[c]).epsilon(2e-3));
  }
}
