// BLEND materials (the forward pass, shaders/lighting/forward.frag) against what the test composites itself from
// frames of the same scene and against the CPU reference's exact compositing: a pane over a lit sphere, glTF OPAQUE,
// MASK and BLEND quads side by side, clustered against brute force, an alpha ramp's fade, and the shadows BLEND
// surfaces cast.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "app/accuracy/accuracy_variants.hpp"
#include "core/scene/gltf_loader.hpp"
#include "debug/transparency_debug_pass.hpp"
#include "reference/reference_renderer.hpp"
#include "tests/cli_util.hpp"
#include "tests/gl_test_context.hpp"
#include "tests/gltf_builder.hpp"
#include "tests/render_util.hpp"

using nlohmann::json;
using pbr::test::GltfBuilder;
using pbr::test::QuadSpec;
using pbr::test::TempDir;

namespace {

constexpr glm::ivec2 kSize{192, 108};

glm::vec3 rgb(const pbr::ImageRgbaF& image, int x, int y) {
  const float* v = image.at(x, y);
  return {v[0], v[1], v[2]};
}

float luminance(const glm::vec3& c) { return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z; }

// With a float G-buffer and radiance target, so that what differs between two frames is the compositing, not
// quantisation.
pbr::test::RenderedFrame renderExact(const pbr::Scene& scene, const pbr::FrameOptions& options, int frames = 2) {
  pbr::RendererConfig config;
  config.hdrFormat = pbr::HdrFormat::Rgba32f;
  config.gbuffer = pbr::GBufferPrecision::Float;
  const pbr::ShaderLibrary shaders;
  return pbr::renderOffscreen(shaders, scene, kSize, options, frames, config);
}

pbr::FrameOptions unshadowed(pbr::ShadingModel model = pbr::ShadingModel::Pbr) {
  pbr::FrameOptions o;
  o.model = model;
  o.shadows.mode = pbr::ShadowMode::None;
  return o;
}

// A unit square pane at `centre`, facing +Z.
glm::mat4 pane(const glm::vec3& centre, const glm::vec2& size) {
  return glm::scale(glm::rotate(glm::translate(glm::mat4(1.0f), centre), glm::radians(90.0f), {1.0f, 0.0f, 0.0f}),
                    {size.x, 1.0f, size.y});
}

pbr::Material material(const glm::vec3& base, float alpha, pbr::AlphaMode mode) {
  pbr::Material m;
  m.baseColor = base;
  m.alpha = alpha;
  m.alphaMode = mode;
  m.roughness = 0.5f;
  return m;
}

// A grey floor (20 m square) seen from `eye` towards `target` (45-degree field of view), with ambient light 0.05.
pbr::Scene floorScene(const glm::vec3& eye, const glm::vec3& target) {
  pbr::Scene scene;
  scene.camera.position = eye;
  scene.camera.target = target;
  scene.camera.fovYDeg = 45.0f;
  scene.ambient = glm::vec3(0.05f);
  scene.addShape(pbr::Shape::Plane, glm::scale(glm::mat4(1.0f), glm::vec3(20.0f)),
                 material(glm::vec3(0.6f), 1.0f, pbr::AlphaMode::Opaque));
  return scene;
}

// Three quads in a row (x = -2.5, 0, 2.5) with the glTF alpha modes `modes`, baseColorFactor alpha 0.3, written as
// a glTF file and seen head-on in front of a grey wall; quads left out where `modes` is empty.
pbr::Scene alphaModeScene(const TempDir& dir, const std::vector<std::string>& modes) {
  GltfBuilder b;
  for (size_t i = 0; i < modes.size(); ++i) {
    QuadSpec spec;
    spec.material = b.addMaterial({{"pbrMetallicRoughness",
                                    {{"baseColorFactor", {0.9, 0.6, 0.2, 0.3}}, {"metallicFactor", 0.0},
                                     {"roughnessFactor", 0.5}}},
                                   {"alphaMode", modes[i]}});
    b.addRootNode({{"mesh", pbr::test::addQuad(b, spec)}, {"translation", {-2.5 + 2.5 * double(i), 0.0, 0.0}}});
  }
  pbr::Scene scene;
  scene.camera.position = {0.0f, 0.0f, 6.0f};
  scene.camera.target = {0.0f, 0.0f, 0.0f};
  scene.camera.fovYDeg = 50.0f;
  scene.camera.nearPlane = 0.1f;
  scene.camera.farPlane = 30.0f;
  scene.ambient = glm::vec3(0.2f);
  if (!modes.empty()) pbr::appendGltf(scene, b.writeGltf(dir.path(), "alpha_modes_" + std::to_string(modes.size())));
  scene.addShape(pbr::Shape::Plane, pane({0.0f, 0.0f, -1.5f}, {20.0f, 10.0f}),
                 material(glm::vec3(0.5f), 1.0f, pbr::AlphaMode::Opaque));
  scene.lights.push_back({{1.0f, 1.5f, 4.0f}, 30.0f, glm::vec3(1.0f), 800.0f});
  return scene;
}

// The pixel at the centre of the quad at world x on the row of the frame's centre.
int columnOf(float worldX) {
  // Head-on from z = 6 with a 50-degree vertical field of view: x projects to x / (6 tan 25deg) of half the height.
  const float halfHeight = 6.0f * std::tan(glm::radians(25.0f));
  return int(std::lround(kSize.x * 0.5f + worldX / halfHeight * kSize.y * 0.5f));
}

}  // namespace

TEST_CASE("transparency: a 0.3-alpha pane over a lit sphere matches the reference's exact compositing") {
  PBR_REQUIRE_GL();
  pbr::Scene scene = floorScene({0.0f, 1.5f, 5.0f}, {0.0f, 0.6f, 0.0f});
  scene.addShape(pbr::Shape::Sphere, glm::scale(glm::translate(glm::mat4(1.0f), {0.0f, 0.7f, -0.5f}), glm::vec3(1.4f)),
                 material({0.8f, 0.3f, 0.2f}, 1.0f, pbr::AlphaMode::Opaque));
  scene.addShape(pbr::Shape::Plane, pane({0.3f, 0.8f, 1.2f}, {1.8f, 1.4f}),
                 material({0.2f, 0.5f, 1.0f}, 0.3f, pbr::AlphaMode::Blend));
  scene.directionalLights = {{glm::normalize(glm::vec3(0.5f, -0.8f, -0.3f)), glm::vec3(1.0f), 3.0f, true}};
  scene.lights.push_back({{1.5f, 2.5f, 2.5f}, 12.0f, glm::vec3(1.0f), 300.0f});
  // The exact BRDF forms the reference evaluates, on float targets (the accuracy ladder's exact-float variant).
  const auto ladder = pbr::accuracyLadder();
  const auto exact = std::find_if(ladder.begin(), ladder.end(), [](const auto& v) { return v.name == "exact-float"; });
  REQUIRE(exact != ladder.end());
  pbr::FrameOptions o = unshadowed();
  o.variant = exact->shading();
  const pbr::test::RenderedFrame gpu = renderExact(scene, o);
  const pbr::reference::ReferenceFrame ref = pbr::reference::renderReference(scene, kSize.x, kSize.y, {});
  const double error = pbr::test::relativeRmse(gpu.hdr, ref.radiance);
  MESSAGE("relative RMSE against the reference: " << error);
  CHECK(error < 0.01);
  // The sphere shows through the pane: without it, the pixels the pane covers over the sphere change.
  pbr::Scene noSphere = scene;
  noSphere.objects.erase(noSphere.objects.begin() + 1);
  const pbr::test::RenderedFrame behind = renderExact(noSphere, o);
  const int x = kSize.x / 2 + 4, y = kSize.y / 2;  // through the pane, on the sphere
  CHECK(std::abs(luminance(rgb(gpu.hdr, x, y)) - luminance(rgb(behind.hdr, x, y))) >
        0.1f * luminance(rgb(behind.hdr, x, y)));
}

TEST_CASE("transparency: glTF OPAQUE, MASK and BLEND quads each render as their alpha mode says") {
  PBR_REQUIRE_GL();
  const TempDir dir;
  const auto render = [&](const std::vector<std::string>& modes) {
    return renderExact(alphaModeScene(dir, modes), unshadowed());
  };
  const pbr::test::RenderedFrame modes = render({"OPAQUE", "MASK", "BLEND"});
  const pbr::test::RenderedFrame opaque = render({"OPAQUE", "OPAQUE", "OPAQUE"});
  const pbr::test::RenderedFrame wall = render({});
  const int y = kSize.y / 2;
  for (int dx = -4; dx <= 4; dx += 2) {
    CAPTURE(dx);
    const int left = columnOf(-2.5f) + dx, middle = columnOf(0.0f) + dx, right = columnOf(2.5f) + dx;
    // OPAQUE ignores alpha: the quad itself.
    CHECK(rgb(modes.hdr, left, y) == rgb(opaque.hdr, left, y));
    // MASK below its cutoff (0.5): cut away, the wall shows.
    CHECK(rgb(modes.hdr, middle, y) == rgb(wall.hdr, middle, y));
    // BLEND: the quad's lit colour over the wall by alpha 0.3, as composited here from the other two frames.
    const glm::vec3 expected = 0.3f * rgb(opaque.hdr, right, y) + 0.7f * rgb(wall.hdr, right, y);
    const glm::vec3 got = rgb(modes.hdr, right, y);
    for (int c = 0; c < 3; ++c) CHECK(got[c] == doctest::Approx(expected[c]).epsilon(1e-4));
    CHECK(got != rgb(wall.hdr, right, y));
  }
}

TEST_CASE("transparency: clustered frames equal brute force with BLEND surfaces, both models and orderings, shadows on") {
  PBR_REQUIRE_GL();
  pbr::Scene scene = floorScene({0.5f, 2.0f, 6.0f}, {0.0f, 0.6f, 0.0f});
  scene.addShape(pbr::Shape::Sphere, glm::translate(glm::mat4(1.0f), {0.0f, 0.7f, -0.5f}),
                 material({0.8f, 0.3f, 0.2f}, 1.0f, pbr::AlphaMode::Opaque));
  // Crossing panes, one double-sided, one solid enough to cast (alpha >= kBlendShadowCutoff).
  pbr::Material blue = material({0.2f, 0.5f, 1.0f}, 0.3f, pbr::AlphaMode::Blend);
  blue.doubleSided = true;
  scene.addShape(pbr::Shape::Plane, pane({0.3f, 0.8f, 1.0f}, {1.6f, 1.4f}), blue);
  scene.addShape(pbr::Shape::Plane,
                 glm::rotate(pane({-0.2f, 0.8f, 0.8f}, {1.2f, 1.2f}), glm::radians(60.0f), {0.0f, 0.0f, 1.0f}),
                 material({1.0f, 0.8f, 0.2f}, 0.7f, pbr::AlphaMode::Blend));
  scene.directionalLights = {{glm::normalize(glm::vec3(0.5f, -0.8f, -0.3f)), glm::vec3(1.0f), 2.0f, true}};
  pbr::PointLight spot{{-2.0f, 2.5f, 2.5f}, 12.0f, glm::vec3(1.0f, 0.9f, 0.8f), 400.0f};
  spot.spot = pbr::SpotCone{glm::normalize(glm::vec3(0.6f, -0.7f, -0.7f)), 0.3f, 0.6f};
  spot.castsShadows = true;
  scene.lights = {{{1.5f, 2.0f, 2.5f}, 10.0f, glm::vec3(0.7f, 0.8f, 1.0f), 300.0f, std::nullopt, true}, spot};
  for (const auto& [model, transparency] :
       {std::pair{pbr::ShadingModel::Pbr, pbr::Transparency::Sorted},
        std::pair{pbr::ShadingModel::BlinnPhong, pbr::Transparency::Sorted},
        std::pair{pbr::ShadingModel::Pbr, pbr::Transparency::Oit},
        std::pair{pbr::ShadingModel::BlinnPhong, pbr::Transparency::Exact}}) {
    CAPTURE(int(model));
    CAPTURE(pbr::toString(transparency));
    pbr::FrameOptions o;
    o.model = model;
    o.transparency = transparency;
    o.shadows.mode = pbr::ShadowMode::Auto;
    o.culling = pbr::Culling::Clustered;
    const pbr::test::RenderedFrame clustered = pbr::test::renderScene(scene, kSize, o);
    o.culling = pbr::Culling::None;
    const pbr::test::RenderedFrame brute = pbr::test::renderScene(scene, kSize, o);
    CHECK(clustered.hdr.pixels == brute.hdr.pixels);
    // The panes are there: the frame differs from the one without them.
    pbr::Scene opaqueOnly = scene;
    opaqueOnly.objects.resize(2);
    const pbr::test::RenderedFrame without = pbr::test::renderScene(opaqueOnly, kSize, o);
    CHECK(pbr::test::maxRelativeDifference(brute.hdr, without.hdr) > 0.1);
  }
}

TEST_CASE("transparency: a base colour alpha ramp from 1 to 0 fades smoothly") {
  PBR_REQUIRE_GL();
  const TempDir dir;
  // Alpha 255 -> 0 across 64 texels, left to right.
  constexpr int kTexels = 64;
  pbr::ImageRgba8 ramp = pbr::test::solidImage(kTexels, 1, {230, 230, 230, 255});
  for (int i = 0; i < kTexels; ++i) ramp.pixels[size_t(i) * 4 + 3] = uint8_t(std::lround(255.0 * (1.0 - i / 63.0)));
  GltfBuilder b;
  b.addPngTexture(dir.path(), "ramp.png", ramp);
  QuadSpec spec;
  spec.material = b.addMaterial({{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}, {"metallicFactor", 0.0}}},
                                 {"alphaMode", "BLEND"}});
  b.addRootNode({{"mesh", pbr::test::addQuad(b, spec)}});
  pbr::Scene scene;
  scene.camera.position = {0.0f, 0.0f, 3.0f};
  scene.camera.fovYDeg = 50.0f;
  scene.ambient = glm::vec3(0.3f);
  pbr::appendGltf(scene, b.writeGltf(dir.path(), "ramp"));
  scene.lights.push_back({{0.0f, 0.0f, 2.0f}, 10.0f, glm::vec3(1.0f), 200.0f});
  const pbr::test::RenderedFrame f = renderExact(scene, unshadowed(), 1);
  // Over nothing (black), the pane's luminance is its lit colour times its alpha: it falls along the ramp, smoothly
  // (no step like a cut-out's), from about full to nothing. The quad spans about 38 pixels either side of centre.
  const int y = kSize.y / 2, first = kSize.x / 2 - 34, last = kSize.x / 2 + 34;
  std::vector<float> row;
  for (int x = first; x <= last; ++x) row.push_back(luminance(rgb(f.hdr, x, y)));
  float largestStep = 0.0f;
  for (size_t i = 1; i < row.size(); ++i) {
    CAPTURE(i);
    CHECK(row[i] <= row[i - 1] + 1e-6f);
    largestStep = std::max(largestStep, row[i - 1] - row[i]);
  }
  const float drop = row.front() - row.back();
  CHECK(drop > 0.8f * row.front());
  CHECK(largestStep < 3.0f * drop / float(row.size() - 1));
}

TEST_CASE("transparency: a BLEND pane casts a shadow where its alpha reaches one half, none below") {
  PBR_REQUIRE_GL();
  for (const float alpha : {0.3f, 0.8f}) {
    CAPTURE(alpha);
    pbr::Scene scene;
    scene.camera.position = {0.0f, 6.0f, 0.0f};
    scene.camera.target = {0.0f, 0.0f, 0.0f};
    scene.camera.up = {0.0f, 0.0f, -1.0f};  // x to the right of the frame
    scene.camera.fovYDeg = 40.0f;
    scene.ambient = glm::vec3(0.02f);
    scene.addShape(pbr::Shape::Plane, glm::scale(glm::mat4(1.0f), glm::vec3(20.0f)),
                   material(glm::vec3(0.6f), 1.0f, pbr::AlphaMode::Opaque));
    // A unit pane a metre above the floor, double-sided, under a sun that throws its shadow 0.75 m along +x: the
    // floor at x = 1 is in its shadow and seen beside it (the pane covers |x| < 0.6 of the floor in the frame).
    pbr::Material paneMaterial = material(glm::vec3(0.9f), alpha, pbr::AlphaMode::Blend);
    paneMaterial.doubleSided = true;
    scene.addShape(pbr::Shape::Plane, glm::translate(glm::mat4(1.0f), {0.0f, 1.0f, 0.0f}), paneMaterial);
    scene.directionalLights = {{glm::normalize(glm::vec3(0.6f, -0.8f, 0.0f)), glm::vec3(1.0f), 2.0f, true}};
    pbr::FrameOptions o;
    o.shadows.mode = pbr::ShadowMode::Auto;
    const pbr::test::RenderedFrame shadowed = renderExact(scene, o);
    o.shadows.mode = pbr::ShadowMode::None;
    const pbr::test::RenderedFrame lit = renderExact(scene, o);
    // Floor x = 1 is 1 / (6 tan 20deg) of the half height right of the centre.
    const int x = kSize.x / 2 + int(std::lround(1.0 / (6.0 * std::tan(glm::radians(20.0))) * kSize.y * 0.5));
    const int y = kSize.y / 2;
    const float inShadow = luminance(rgb(shadowed.hdr, x, y)), unshadowed = luminance(rgb(lit.hdr, x, y));
    if (alpha < pbr::kBlendShadowCutoff) {
      CHECK(inShadow == doctest::Approx(unshadowed).epsilon(1e-4));
    } else {
      CHECK(inShadow < 0.05f * unshadowed);
    }
    // Beyond the shadow the floor is lit either way.
    CHECK(luminance(rgb(shadowed.hdr, 8, y)) == doctest::Approx(luminance(rgb(lit.hdr, 8, y))).epsilon(1e-4));
  }
}

namespace {

// Two panes crossing along a vertical line (each in front of the other on one side of it), a third over both that
// intersects neither, over a floor and a sphere: the ordering case sorting cannot get right.
pbr::Scene crossingPanes() {
  pbr::Scene scene = floorScene({0.0f, 1.2f, 5.0f}, {0.0f, 0.8f, 0.0f});
  scene.addShape(pbr::Shape::Sphere, glm::scale(glm::translate(glm::mat4(1.0f), {0.3f, 0.6f, -1.5f}), glm::vec3(1.2f)),
                 material({0.8f, 0.8f, 0.8f}, 1.0f, pbr::AlphaMode::Opaque));
  const auto turned = [](float degrees) {
    return glm::rotate(glm::translate(glm::mat4(1.0f), {0.0f, 0.8f, 0.5f}), glm::radians(degrees), {0.0f, 1.0f, 0.0f}) *
           pane(glm::vec3(0.0f), {1.6f, 1.2f});
  };
  scene.addShape(pbr::Shape::Plane, turned(35.0f), material({1.0f, 0.2f, 0.1f}, 0.5f, pbr::AlphaMode::Blend));
  scene.addShape(pbr::Shape::Plane, turned(-35.0f), material({0.1f, 0.3f, 1.0f}, 0.4f, pbr::AlphaMode::Blend));
  scene.addShape(pbr::Shape::Plane, pane({0.4f, 0.9f, 1.4f}, {0.8f, 0.6f}),
                 material({0.2f, 1.0f, 0.3f}, 0.6f, pbr::AlphaMode::Blend));
  scene.directionalLights = {{glm::normalize(glm::vec3(0.4f, -0.8f, -0.4f)), glm::vec3(1.0f), 3.0f, true}};
  scene.lights.push_back({{-1.5f, 2.5f, 2.5f}, 12.0f, glm::vec3(1.0f), 300.0f});
  return scene;
}

}  // namespace

TEST_CASE("transparency: crossing panes, sorted wrong only where they overlap, oit within its bound, exact exact") {
  PBR_REQUIRE_GL();
  const pbr::Scene scene = crossingPanes();
  const auto ladder = pbr::accuracyLadder();
  const auto exact = std::find_if(ladder.begin(), ladder.end(), [](const auto& v) { return v.name == "exact-float"; });
  REQUIRE(exact != ladder.end());
  pbr::FrameOptions o = unshadowed();
  o.variant = exact->shading();
  const pbr::reference::ReferenceFrame ref = pbr::reference::renderReference(scene, kSize.x, kSize.y, {});
  o.transparency = pbr::Transparency::Sorted;
  const pbr::test::RenderedFrame sorted = renderExact(scene, o);
  o.transparency = pbr::Transparency::Oit;
  const pbr::test::RenderedFrame oit = renderExact(scene, o);
  // Which pixels the two crossing panes both cover: each alone changes the frame there.
  const auto without = [&](size_t object) {
    pbr::Scene s = scene;
    s.objects.erase(s.objects.begin() + std::ptrdiff_t(object));
    return renderExact(s, o).hdr;
  };
  const pbr::ImageRgbaF noRed = without(2), noBlue = without(3);
  size_t overlapping = 0, wrongInOverlap = 0, wrongElsewhere = 0;
  for (int y = 0; y < kSize.y; ++y) {
    for (int x = 0; x < kSize.x; ++x) {
      const glm::vec3 r = rgb(ref.radiance, x, y);
      const bool both = rgb(noRed, x, y) != rgb(oit.hdr, x, y) && rgb(noBlue, x, y) != rgb(oit.hdr, x, y);
      const bool wrong = glm::length(rgb(sorted.hdr, x, y) - r) > 1e-2f * std::max(glm::length(r), 1e-3f);
      overlapping += both ? 1 : 0;
      wrongInOverlap += both && wrong ? 1 : 0;
      wrongElsewhere += !both && wrong ? 1 : 0;
    }
  }
  MESSAGE("sorted: " << wrongInOverlap << " of " << overlapping << " overlapping pixels off by over 1 %, "
                     << wrongElsewhere << " elsewhere");
  // Sorting by centres orders the crossing panes one way: right on one side of their crossing, wrong on the other.
  CHECK(wrongInOverlap > overlapping / 4);
  CHECK(wrongInOverlap < overlapping);
  // Elsewhere at most a pixel whose centre lies on a pane's edge, covered in one frame and not the other.
  CHECK(wrongElsewhere <= 8);
  o.transparency = pbr::Transparency::Exact;
  const pbr::test::RenderedFrame exactLists = renderExact(scene, o);
  const double sortedError = pbr::test::relativeRmse(sorted.hdr, ref.radiance), oitError = pbr::test::relativeRmse(oit.hdr, ref.radiance);
  const double exactError = pbr::test::relativeRmse(exactLists.hdr, ref.radiance);
  MESSAGE("relative RMSE against the reference: sorted " << sortedError << ", oit " << oitError << ", exact "
                                                         << exactError);
  CHECK(oitError < 0.05);
  // The per-pixel lists order every fragment: only their half-float colour is left (at most 2^-11 relative).
  CHECK(exactError < 2e-3);
  CHECK(exactLists.stats.droppedLayers == 0);
}

TEST_CASE("transparency debug view: each pixel shows how many BLEND layers cover it") {
  PBR_REQUIRE_GL();
  const pbr::Scene scene = crossingPanes();
  pbr::FrameOptions o = unshadowed();
  const pbr::test::RenderedFrame lit = renderExact(scene, o);
  // The layers each pixel shows, counted here: each pane alone changes the lit frame where it covers a pixel.
  std::vector<int> layers(size_t(kSize.x) * kSize.y, 0);
  for (size_t pane = 2; pane < scene.objects.size(); ++pane) {
    pbr::Scene without = scene;
    without.objects.erase(without.objects.begin() + std::ptrdiff_t(pane));
    const pbr::ImageRgbaF f = renderExact(without, o).hdr;
    for (int y = 0; y < kSize.y; ++y) {
      for (int x = 0; x < kSize.x; ++x) layers[size_t(y) * kSize.x + x] += rgb(f, x, y) != rgb(lit.hdr, x, y);
    }
  }
  o.debug = pbr::DebugChannel::Transparency;
  const pbr::test::RenderedFrame view = renderExact(scene, o);
  // heat.glsl's ramp at count / 8: black, blue, cyan, green, yellow, red at 0, 1.6, 3.2, 4.8, 6.4 and 8 layers.
  const auto heat = [](float t) {
    const glm::vec3 stops[6] = {glm::vec3(0.0f), {0.0f, 0.1f, 0.9f}, {0.0f, 0.8f, 0.9f}, {0.1f, 0.85f, 0.1f},
                                {1.0f, 0.9f, 0.0f}, {1.0f, 0.05f, 0.0f}};
    const float x = std::clamp(t, 0.0f, 1.0f) * 5.0f;
    const int i = std::min(int(x), 4);
    return glm::mix(stops[i], stops[i + 1], x - float(i));
  };
  size_t seen[4] = {0, 0, 0, 0};
  // The upper half of the frame (captures hold rows top-down): the legend sits at the bottom.
  for (int y = 0; y < kSize.y / 2; ++y) {
    for (int x = 0; x < kSize.x; ++x) {
      const int n = layers[size_t(y) * kSize.x + x];
      const uint8_t* p = &view.ldr.pixels[(size_t(y) * kSize.x + x) * 4];
      CAPTURE(x);
      CAPTURE(y);
      CAPTURE(n);
      if (n == 0) {
        CHECK((p[0] == p[1] && p[1] == p[2]));  // the grey no-data pattern
      } else {
        // The ramp's values are stored as they are (the debug views write the RGBA8 frame directly).
        const glm::vec3 expected = heat(float(n) / float(pbr::kMaxShownLayers));
        for (int c = 0; c < 3; ++c) CHECK(std::abs(int(p[c]) - int(std::lround(expected[c] * 255.0f))) <= 1);
      }
      ++seen[std::min(n, 3)];
    }
  }
  MESSAGE("pixels with 0, 1, 2, 3 layers: " << seen[0] << ", " << seen[1] << ", " << seen[2] << ", " << seen[3]);
  CHECK(seen[1] > 0);
  CHECK(seen[2] > 0);
}

TEST_CASE("transparency: exact lists composite the nearest layers of a pixel and count the ones they leave out") {
  PBR_REQUIRE_GL();
  // A stack of panes one behind the other, more than a pixel composites.
  pbr::Scene scene = floorScene({0.0f, 0.5f, 6.0f}, {0.0f, 0.5f, 0.0f});
  const int panes = int(pbr::kMaxLayersPerPixel) + 8;
  for (int i = 0; i < panes; ++i) {
    scene.addShape(pbr::Shape::Plane, pane({0.0f, 0.5f, -0.05f * float(i)}, {2.0f, 2.0f}),
                   material({0.9f, 0.5f, 0.2f}, 0.2f, pbr::AlphaMode::Blend));
  }
  scene.lights.push_back({{0.0f, 2.0f, 3.0f}, 20.0f, glm::vec3(1.0f), 400.0f});
  pbr::FrameOptions o = unshadowed();
  o.transparency = pbr::Transparency::Exact;
  const pbr::test::RenderedFrame f = renderExact(scene, o);
  // The panes cover the frame's centre: every pixel there leaves out its farthest 8.
  CHECK(f.stats.droppedLayers >= 8u);
  // What is left out lies behind 40 panes of alpha 0.2 (0.8^40 = 1.3e-4 of it shows): the frame matches sorted.
  o.transparency = pbr::Transparency::Sorted;
  const pbr::test::RenderedFrame sorted = renderExact(scene, o);
  const int x = kSize.x / 2, y = kSize.y / 2;
  for (int c = 0; c < 3; ++c) CHECK(rgb(f.hdr, x, y)[c] == doctest::Approx(rgb(sorted.hdr, x, y)[c]).epsilon(2e-3));
}

TEST_CASE("transparency: the exact lists take 8 nodes a pixel, fewer where a storage block holds fewer, else refuse") {
  const size_t pixels = 1000;
  const size_t header = sizeof(pbr::LayerListHeader);
  CHECK(pbr::layerListBytes(pixels, uint64_t(1) << 30) == header + pixels * (4 + 16 * pbr::kLayerNodesPerPixel));
  // A block of 64 KiB holds the heads and 3.8 nodes a pixel: the lists take it whole, in nodes of 16 bytes.
  CHECK(pbr::layerListBytes(pixels, 65536) == 65536);
  // Under the heads and a node a pixel: one line naming the option.
  CHECK_THROWS_WITH_AS(pbr::layerListBytes(pixels, 16000),
                       doctest::Contains("--transparency exact: a frame of 1000 pixels needs"), std::runtime_error);
}
