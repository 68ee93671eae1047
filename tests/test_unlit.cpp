// KHR_materials_unlit: an unlit surface's radiance is its base colour, whatever lights the scene, opaque or BLEND,
// clustered or brute force, against the CPU reference; a glTF file requiring the extension loads it.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "core/scene/gltf_loader.hpp"
#include "reference/reference_renderer.hpp"
#include "tests/cli_util.hpp"
#include "tests/gl_test_context.hpp"
#include "tests/gltf_builder.hpp"
#include "tests/render_util.hpp"

namespace {

constexpr glm::ivec2 kSize{160, 90};
const glm::vec3 kUnlitColor{0.2f, 0.6f, 0.9f};

glm::vec3 rgb(const pbr::ImageRgbaF& image, int x, int y) {
  const float* v = image.at(x, y);
  return {v[0], v[1], v[2]};
}

pbr::Material material(const glm::vec3& base, bool unlit) {
  pbr::Material m;
  m.baseColor = base;
  m.roughness = 0.4f;
  m.unlit = unlit;
  return m;
}

// Two spheres side by side on a lit floor, the left one unlit, under a point, a spot and a directional light and
// ambient light: every kind of light the unlit one must not reflect.
pbr::Scene spheres() {
  pbr::Scene scene;
  scene.camera.position = {0.0f, 1.0f, 6.0f};
  scene.camera.target = {0.0f, 0.8f, 0.0f};
  scene.camera.fovYDeg = 40.0f;
  scene.ambient = glm::vec3(0.1f);
  scene.addShape(pbr::Shape::Plane, glm::scale(glm::mat4(1.0f), glm::vec3(20.0f)), material(glm::vec3(0.5f), false));
  for (const float x : {-1.2f, 1.2f}) {
    scene.addShape(pbr::Shape::Sphere, glm::scale(glm::translate(glm::mat4(1.0f), {x, 1.0f, 0.0f}), glm::vec3(1.8f)),
                   material(x < 0.0f ? kUnlitColor : glm::vec3(0.7f, 0.3f, 0.2f), x < 0.0f));
  }
  scene.lights.push_back({{0.0f, 3.0f, 3.0f}, 15.0f, glm::vec3(1.0f), 600.0f});
  pbr::PointLight spot{{-1.2f, 3.5f, 1.0f}, 10.0f, glm::vec3(1.0f, 0.9f, 0.8f), 900.0f};
  spot.spot = pbr::SpotCone{glm::normalize(glm::vec3(0.0f, -1.0f, -0.4f)), 0.3f, 0.6f};
  scene.lights.push_back(spot);
  scene.directionalLights = {{glm::normalize(glm::vec3(0.3f, -1.0f, -0.5f)), glm::vec3(1.0f), 2.0f, false}};
  return scene;
}

// The pixel at the middle of the sphere at world x (head-on enough that the sphere's centre projects near it).
glm::ivec2 sphereCentre(const pbr::Scene& scene, float x) {
  const glm::mat4 viewProjection =
      glm::perspective(glm::radians(scene.camera.fovYDeg), float(kSize.x) / kSize.y, 0.1f, 100.0f) *
      glm::lookAt(scene.camera.position, scene.camera.target, glm::vec3(0.0f, 1.0f, 0.0f));
  const glm::vec4 clip = viewProjection * glm::vec4(x, 1.0f, 0.0f, 1.0f);
  const glm::vec2 ndc = glm::vec2(clip) / clip.w;
  return {int((ndc.x * 0.5f + 0.5f) * kSize.x), int((ndc.y * 0.5f + 0.5f) * kSize.y)};
}

}  // namespace

TEST_CASE("unlit: the surface's radiance is its base colour under every light, in both models and culling paths") {
  PBR_REQUIRE_GL();
  const pbr::Scene scene = spheres();
  const glm::ivec2 unlit = sphereCentre(scene, -1.2f), lit = sphereCentre(scene, 1.2f);
  for (const pbr::ShadingModel model : {pbr::ShadingModel::Pbr, pbr::ShadingModel::BlinnPhong}) {
    pbr::FrameOptions clustered, brute;
    clustered.model = brute.model = model;
    brute.culling = pbr::Culling::None;
    const pbr::test::RenderedFrame a = pbr::test::renderScene(scene, kSize, clustered);
    const pbr::test::RenderedFrame b = pbr::test::renderScene(scene, kSize, brute);
    CHECK(a.hdr.pixels == b.hdr.pixels);
    // Over the whole unlit disc: the base colour (within the radiance target's fp16 rounding).
    int inside = 0;
    for (int y = unlit.y - 6; y <= unlit.y + 6; ++y) {
      for (int x = unlit.x - 6; x <= unlit.x + 6; ++x, ++inside) {
        CAPTURE(x);
        CAPTURE(y);
        const glm::vec3 c = rgb(a.hdr, x, y);
        for (int ch = 0; ch < 3; ++ch) CHECK(c[ch] == doctest::Approx(kUnlitColor[ch]).epsilon(1e-3));
      }
    }
    CHECK(inside == 169);
    // The lit sphere beside it is shaded: its centre differs from its base colour.
    CHECK(std::abs(rgb(a.hdr, lit.x, lit.y).x - 0.7f) > 0.05f);
  }
  // Without the flag, the same sphere reflects the lights.
  pbr::Scene litOnly = scene;
  litOnly.objects[1].material.unlit = false;
  const pbr::test::RenderedFrame shaded = pbr::test::renderScene(litOnly, kSize, pbr::FrameOptions{});
  CHECK(glm::length(rgb(shaded.hdr, unlit.x, unlit.y) - kUnlitColor) > 0.05f);
}

TEST_CASE("unlit: the GPU frame matches the CPU reference, and a BLEND unlit pane composites its base colour") {
  PBR_REQUIRE_GL();
  pbr::Scene scene = spheres();
  pbr::FrameOptions o;
  o.shadows.mode = pbr::ShadowMode::None;
  const pbr::test::RenderedFrame gpu = pbr::test::renderScene(scene, kSize, o);
  const pbr::reference::ReferenceFrame ref = pbr::reference::renderReference(scene, kSize.x, kSize.y, {});
  // Every interior pixel of the unlit sphere agrees with the reference's base colour.
  int compared = 0;
  for (int y = 0; y < kSize.y; ++y) {
    for (int x = 0; x < kSize.x; ++x) {
      if (ref.objectIds[size_t(y) * kSize.x + x] != 1 || !ref.interior(x, y)) continue;
      ++compared;
      const glm::vec3 g = rgb(gpu.hdr, x, y), r = rgb(ref.radiance, x, y);
      CHECK(glm::length(g - r) < 2e-3f);
    }
  }
  MESSAGE(compared << " unlit pixels compared with the reference");
  CHECK(compared > 300);
  // An unlit pane of alpha 0.4 in front of the camera over an unlit black backdrop: 0.4 x its base colour.
  pbr::Scene pane;
  pane.camera = scene.camera;
  pane.ambient = glm::vec3(0.3f);
  pane.lights = scene.lights;
  pbr::Material backdrop = material(glm::vec3(0.0f), true);
  pane.addShape(pbr::Shape::Plane,
                glm::rotate(glm::translate(glm::mat4(1.0f), {0.0f, 0.8f, -2.0f}), glm::radians(90.0f), {1, 0, 0}) *
                    glm::scale(glm::mat4(1.0f), glm::vec3(30.0f)),
                backdrop);
  pbr::Material glass = material(kUnlitColor, true);
  glass.alpha = 0.4f;
  glass.alphaMode = pbr::AlphaMode::Blend;
  pane.addShape(pbr::Shape::Plane,
                glm::rotate(glm::translate(glm::mat4(1.0f), {0.0f, 0.8f, 2.0f}), glm::radians(90.0f), {1, 0, 0}) *
                    glm::scale(glm::mat4(1.0f), glm::vec3(2.0f)),
                glass);
  const pbr::test::RenderedFrame blended = pbr::test::renderScene(pane, kSize, o);
  const glm::vec3 c = rgb(blended.hdr, kSize.x / 2, kSize.y / 2);
  for (int ch = 0; ch < 3; ++ch) CHECK(c[ch] == doctest::Approx(0.4f * kUnlitColor[ch]).epsilon(2e-3));
}

TEST_CASE("unlit: a glTF file requiring KHR_materials_unlit loads its material as unlit") {
  const pbr::test::TempDir dir;
  pbr::test::GltfBuilder b;
  pbr::test::QuadSpec spec;
  spec.material = b.addMaterial({{"pbrMetallicRoughness", {{"baseColorFactor", {0.2, 0.6, 0.9, 1.0}}}},
                                 {"extensions", {{"KHR_materials_unlit", nlohmann::json::object()}}}});
  b.addRootNode({{"mesh", pbr::test::addQuad(b, spec)}});
  b.doc["extensionsUsed"] = b.doc["extensionsRequired"] = {"KHR_materials_unlit"};
  pbr::Scene scene;
  pbr::appendGltf(scene, b.writeGltf(dir.path(), "unlit"));
  REQUIRE(scene.objects.size() == 1);
  CHECK(scene.objects[0].material.unlit);
  CHECK(scene.objects[0].material.baseColor == glm::vec3(0.2f, 0.6f, 0.9f));
}
