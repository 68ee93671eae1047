// The stability matrix of issue 6: degenerate materials, geometry, lights and cameras. Each case renders a tiny
// frame with the standard PBR model, an all-approximations PBR variant and Blinn-Phong, by brute force and
// clustered, and checks that the HDR read-back is finite, within physical bounds, and the same on both paths.
// docs/stability.md lists the failure modes these cases found and where they are handled.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <functional>

#include <glm/gtc/matrix_transform.hpp>

#include "renderer/renderer.hpp"
#include "core/scene/random.hpp"
#include "tests/gl_test_context.hpp"

using namespace pbr;

namespace {

constexpr int kWidth = 32, kHeight = 18;

// A floor, a sphere resting on it and one light above them.
Scene baseScene() {
  Scene s;
  s.name = "stability";
  s.camera.position = glm::vec3(0.0f, 1.5f, 3.0f);
  s.camera.target = glm::vec3(0.0f, 0.4f, 0.0f);
  s.ambient = glm::vec3(0.03f);
  s.addShape(Shape::Plane, glm::scale(glm::mat4(1.0f), glm::vec3(6.0f, 1.0f, 6.0f)), Material{glm::vec3(0.5f), 0.6f, 0.0f});
  s.addShape(Shape::Sphere, glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.5f, 0.0f)),
             Material{glm::vec3(0.9f, 0.6f, 0.4f), 0.3f, 1.0f});
  s.lights.push_back({glm::vec3(0.5f, 1.5f, 0.5f), 5.0f, glm::vec3(1.0f), 400.0f});
  return s;
}

struct Check {
  const char* name;
  FrameOptions options;
  float maxValue;
};

std::vector<Check> checks() {
  FrameOptions standard, approximate, blinnPhong;
  approximate.variant = parseShadingVariant("visibility=hammon,ndf=beckmann,fresnel=exact,diffuse=burley");
  blinnPhong.model = ShadingModel::BlinnPhong;
  return {{"pbr", standard, 65504.0f}, {"pbr approximations", approximate, 65504.0f}, {"blinn-phong", blinnPhong, 1.0f}};
}

// Renders `scene` every way of checks() and returns how many pixels were non-zero in the standard PBR frame.
size_t checkStable(const Scene& scene) {
  const ShaderLibrary shaders;
  Renderer renderer(shaders, scene, kWidth, kHeight);
  Profiler profiler(TimingMode::Serializing);
  size_t lit = 0;
  for (Check c : checks()) {
    CAPTURE(c.name);
    ImageRgbaF brute, clustered;
    c.options.culling = Culling::None;
    renderer.renderFrame(c.options, profiler, {nullptr, &brute});
    c.options.culling = Culling::Clustered;
    renderer.renderFrame(c.options, profiler);  // sizes the light-index list from measured demand
    renderer.renderFrame(c.options, profiler, {nullptr, &clustered});
    size_t bad = 0;
    for (size_t i = 0; i < brute.pixels.size(); ++i) {
      const float v = brute.pixels[i];
      if (!std::isfinite(v) || v < 0.0f || v > c.maxValue) ++bad;
      if (c.options.model == ShadingModel::Pbr && c.options.variant == ShadingVariant{} && i % 4 != 3 && v > 0.0f) ++lit;
    }
    CHECK(bad == 0);
    CHECK(clustered.pixels == brute.pixels);
  }
  profiler.takeResults(true);
  return lit;
}

Scene withMaterials(const std::function<void(Material&)>& change) {
  Scene s = baseScene();
  for (SceneObject& o : s.objects) change(o.material);
  return s;
}

Scene withLight(glm::vec3 position, float radius, float power) {
  Scene s = baseScene();
  s.lights = {{position, radius, glm::vec3(1.0f), power}};
  return s;
}

}  // namespace

TEST_CASE("stability: roughness 0 and 1") {
  PBR_REQUIRE_GL();
  checkStable(withMaterials([](Material& m) { m.roughness = 0.0f; }));
  checkStable(withMaterials([](Material& m) { m.roughness = 1.0f; }));
}

TEST_CASE("stability: transmission through thin walls and volumes, at the extremes of its factors") {
  PBR_REQUIRE_GL();
  // Both objects transmissive (the floor seen through the sphere and the sphere through the floor): smooth and
  // rough, ior 1 (no refraction) and 0 (F0 1), a black attenuation colour over no distance and a huge thickness,
  // transmission 1 over a black base colour, and a metal.
  const std::function<void(Material&)> cases[] = {
      [](Material& m) { m.transmission = 1.0f, m.roughness = 0.0f; },
      [](Material& m) { m.transmission = 1.0f, m.roughness = 1.0f, m.ior = 1.0f; },
      [](Material& m) { m.transmission = 1.0f, m.ior = 0.0f, m.thickness = 1.0f; },
      [](Material& m) {
        m.transmission = 1.0f, m.thickness = 1e6f, m.attenuationColor = glm::vec3(0.0f);
        m.attenuationDistance = 1e-6f;
      },
      [](Material& m) { m.transmission = 1.0f, m.thickness = 0.0f, m.attenuationColor = glm::vec3(0.0f); },
      [](Material& m) { m.transmission = 1.0f, m.baseColor = glm::vec3(0.0f), m.metalness = 1.0f; },
  };
  for (const auto& change : cases) checkStable(withMaterials(change));
}

TEST_CASE("stability: base colour 0 and 1, dielectric and metal") {
  PBR_REQUIRE_GL();
  for (float metalness : {0.0f, 1.0f}) {
    checkStable(withMaterials([&](Material& m) { m.baseColor = glm::vec3(0.0f), m.metalness = metalness; }));
    checkStable(withMaterials([&](Material& m) { m.baseColor = glm::vec3(1.0f), m.metalness = metalness; }));
  }
}

TEST_CASE("stability: n.v = 0 (a plane seen edge-on, sphere silhouettes) and n.v < 0 (normal map facing away)") {
  PBR_REQUIRE_GL();
  Scene edgeOn = baseScene();
  edgeOn.camera.position = glm::vec3(0.0f, 1e-4f, 3.0f);
  edgeOn.camera.target = glm::vec3(0.0f, 1e-4f, 0.0f);
  checkStable(edgeOn);
  // Tangent-space normal (0, 0, -1): every shaded normal points into the surface, away from the camera.
  Scene away = baseScene();
  away.textures.push_back({"away", 1, 1, {128, 128, 0, 255}, false});
  for (SceneObject& o : away.objects) o.material.normalTexture = 0;
  checkStable(away);
}

TEST_CASE("stability: light at distance 0, inside a surface, radius 0, power 0 and 1e9") {
  PBR_REQUIRE_GL();
  checkStable(withLight(glm::vec3(0.0f), 5.0f, 400.0f));               // on the floor
  checkStable(withLight(glm::vec3(0.0f, 1.0f, 0.0f), 5.0f, 400.0f));   // on the sphere's top
  checkStable(withLight(glm::vec3(0.0f, 0.5f, 0.0f), 5.0f, 400.0f));   // inside the sphere
  checkStable(withLight(glm::vec3(0.0f, -1.0f, 0.0f), 5.0f, 400.0f));  // under the floor
  checkStable(withLight(glm::vec3(0.5f, 1.5f, 0.5f), 0.0f, 400.0f));
  checkStable(withLight(glm::vec3(0.5f, 1.5f, 0.5f), 5.0f, 0.0f));
  checkStable(withLight(glm::vec3(0.5f, 1.5f, 0.5f), 5.0f, 1e9f));
}

TEST_CASE("stability: camera near/far ratio 1e6") {
  PBR_REQUIRE_GL();
  Scene s = baseScene();
  s.camera.nearPlane = 1e-3f;
  s.camera.farPlane = 1e3f;
  CHECK(checkStable(s) > 0);
}

TEST_CASE("stability: 0 lights and 100,000 lights") {
  PBR_REQUIRE_GL();
  Scene none = baseScene();
  none.lights.clear();
  checkStable(none);
  Scene many = baseScene();
  many.lights.clear();
  Pcg32 rng(6);
  for (int i = 0; i < 100000; ++i) {
    many.lights.push_back({glm::vec3(rng.uniform(-3.0f, 3.0f), rng.uniform(0.05f, 2.0f), rng.uniform(-3.0f, 3.0f)),
                           rng.uniform(0.2f, 1.0f), glm::vec3(1.0f), rng.uniform(0.1f, 2.0f)});
  }
  CHECK(checkStable(many) > 0);
}

TEST_CASE("stability: a 1e9-lumen light stays finite and in range in every HDR target format") {
  PBR_REQUIRE_GL();
  const Scene s = withLight(glm::vec3(0.5f, 1.5f, 0.5f), 5.0f, 1e9f);
  const ShaderLibrary shaders;
  for (HdrFormat format : {HdrFormat::Rgba16f, HdrFormat::R11g11b10f, HdrFormat::Rgba32f}) {
    CAPTURE(toString(format));
    RendererConfig config;
    config.hdrFormat = format;
    Renderer renderer(shaders, s, kWidth, kHeight, config);
    Profiler profiler(TimingMode::Serializing);
    ImageRgbaF hdr;
    renderer.renderFrame(FrameOptions{}, profiler, {nullptr, &hdr});
    float largest = 0.0f;
    size_t bad = 0;
    for (size_t i = 0; i < hdr.pixels.size(); ++i) {
      if (!std::isfinite(hdr.pixels[i]) || hdr.pixels[i] < 0.0f || hdr.pixels[i] > 65504.0f) ++bad;
      else largest = std::max(largest, hdr.pixels[i]);
    }
    CHECK(bad == 0);
    CHECK(largest > 1e4f);  // the light does saturate the target: the clamp is what keeps it finite
    profiler.takeResults(true);
  }
}
