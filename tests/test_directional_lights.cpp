// Directional lights and physical exposure: frames against the double-precision reference and against the
// formulas (Lo = f E n.l; exposure 1 / (1.2 2^EV100)), in process and through `pbr render`.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "app/accuracy/accuracy_metrics.hpp"
#include "core/scene/image.hpp"
#include "core/scene/scene_json.hpp"
#include "reference/display_transform.hpp"
#include "reference/reference_brdf.hpp"
#include "reference/reference_renderer.hpp"
#include "renderer/display_image.hpp"
#include "renderer/offscreen.hpp"
#include "tests/cli_util.hpp"
#include "tests/gl_test_context.hpp"

namespace ref = pbr::reference;
using glm::dvec3;
using pbr::test::TempDir;

namespace {

// A floor of 40 x 40 units under `lights` alone (no ambient, no point light), seen from `eye`.
pbr::Scene floorScene(const pbr::Material& material, const std::vector<pbr::DirectionalLight>& lights,
                      const glm::vec3& eye, const glm::vec3& up = {0.0f, 1.0f, 0.0f}) {
  pbr::Scene s;
  s.name = "directional floor";
  s.camera.position = eye;
  s.camera.target = glm::vec3(0.0f);
  s.camera.up = up;
  s.camera.fovYDeg = 45.0f;
  s.addShape(pbr::Shape::Plane, glm::scale(glm::mat4(1.0f), glm::vec3(40.0f)), material);
  s.directionalLights = lights;
  return s;
}

pbr::Material material(float base, float roughness, float metalness) {
  pbr::Material m;
  m.baseColor = glm::vec3(base);
  m.roughness = roughness;
  m.metalness = metalness;
  return m;
}

// A directional light travelling along `direction` (normalised here).
pbr::DirectionalLight sun(const glm::vec3& direction, float lux, const glm::vec3& color = glm::vec3(1.0f)) {
  return {glm::normalize(direction), color, lux};
}

// An odd frame from straight above: the centre pixel's ray is the view axis, so there V = N = +Y.
constexpr int kCentred = 33;
const glm::vec3 kAbove{0.0f, 5.0f, 0.0f};
const glm::vec3 kAboveUp{0.0f, 0.0f, -1.0f};

int srgb8(double linear) {
  return static_cast<int>(std::lround(ref::srgbEncode(std::clamp(linear, 0.0, 1.0)) * 255.0));
}

}  // namespace

TEST_CASE("directional lights: a floor's radiance is f E n.l, as the double-precision reference ray-casts it") {
  PBR_REQUIRE_GL();
  const pbr::ShaderLibrary shaders;
  const glm::ivec2 size{96, 54};
  pbr::FrameOptions options;
  options.variant = pbr::parseShadingVariant("fresnel=exact");  // the reference's terms
  pbr::RendererConfig config;  // float G-buffer and target: only float arithmetic separates GPU and reference
  config.gbuffer = pbr::GBufferPrecision::Float;
  config.hdrFormat = pbr::HdrFormat::Rgba32f;
  // A coloured sun at about 63 degrees from the normal and a second, dimmer one low in the sky.
  const std::vector<pbr::DirectionalLight> lights = {sun({1.0f, -0.5f, 0.3f}, 3.0f, {1.0f, 0.8f, 0.6f}),
                                                     sun({-0.2f, -1.0f, -0.4f}, 0.7f)};
  for (const pbr::Material& m : {material(0.8f, 0.5f, 0.0f), material(0.9f, 0.3f, 1.0f)}) {
    CAPTURE(m.metalness);
    const pbr::Scene scene = floorScene(m, lights, {0.0f, 3.0f, 4.0f});
    const ref::ReferenceFrame expected = ref::renderReference(scene, size.x, size.y);
    const pbr::RenderedFrames gpu = pbr::renderOffscreen(shaders, scene, size, options, 1, config);
    const pbr::ErrorMetrics e =
        pbr::measureError(gpu.hdr, gpu.ldr, expected, pbr::displayImage(shaders, expected.radiance, 1.0f));
    MESSAGE("relative RMSE against the reference: " << e.relativeRmse << " over " << e.pixels << " pixels");
    CHECK(e.pixels > size_t(size.x * size.y / 3));
    CHECK(e.relativeRmse < 1e-3);
    // The frame is lit: a wrong sign of the direction would leave the floor black (and the reference with it).
    const float* centre = gpu.hdr.at(size.x / 2, size.y / 2);
    CHECK(centre[0] > 1e-3f);
  }
}

TEST_CASE("directional lights: a light from below the surface adds nothing in either model") {
  PBR_REQUIRE_GL();
  const pbr::ShaderLibrary shaders;
  const glm::ivec2 size{48, 27};
  for (const pbr::ShadingModel model : {pbr::ShadingModel::Pbr, pbr::ShadingModel::BlinnPhong}) {
    pbr::FrameOptions options;
    options.model = model;
    const pbr::Material m = material(0.8f, 0.5f, 0.0f);
    const pbr::RenderedFrames none = pbr::renderOffscreen(shaders, floorScene(m, {}, {0.0f, 3.0f, 4.0f}), size, options, 1);
    const pbr::RenderedFrames below = pbr::renderOffscreen(
        shaders, floorScene(m, {sun({0.3f, 1.0f, 0.0f}, 1e5f)}, {0.0f, 3.0f, 4.0f}), size, options, 1);
    CHECK(below.hdr.pixels == none.hdr.pixels);
  }
}

TEST_CASE("directional lights: Blinn-Phong takes the light's colour as its strength") {
  PBR_REQUIRE_GL();
  const pbr::ShaderLibrary shaders;
  pbr::FrameOptions options;
  options.model = pbr::ShadingModel::BlinnPhong;
  pbr::RendererConfig config;
  config.gbuffer = pbr::GBufferPrecision::Float;
  config.hdrFormat = pbr::HdrFormat::Rgba32f;
  const glm::vec3 color{0.6f, 0.5f, 0.4f};
  const glm::vec3 direction = glm::normalize(glm::vec3(-1.0f, -2.0f, 0.5f));
  // The illuminance plays no part in an LDR model: 1e5 lux and 1 lux give the same frame.
  const pbr::Material m = material(0.5f, 0.5f, 0.0f);
  const pbr::Scene bright = floorScene(m, {{direction, color, 1e5f}}, kAbove, kAboveUp);
  const pbr::Scene dim = floorScene(m, {{direction, color, 1.0f}}, kAbove, kAboveUp);
  const pbr::RenderedFrames f = pbr::renderOffscreen(shaders, bright, {kCentred, kCentred}, options, 1, config);
  CHECK(f.hdr.pixels == pbr::renderOffscreen(shaders, dim, {kCentred, kCentred}, options, 1, config).hdr.pixels);

  // The centre pixel from the formulas: ambient 0.02 (1 - m) c, diffuse (1 - m) c n.l, specular F0 (n.h)^n with
  // n = 2 / a^2 - 2, a = roughness^2, F0 = 0.04 for a dielectric.
  const dvec3 N(0.0, 1.0, 0.0), V(0.0, 1.0, 0.0), L = -dvec3(direction);
  const double NoL = glm::dot(N, L), NoH = glm::dot(N, glm::normalize(V + L));
  const double a = 0.25, shininess = 2.0 / (a * a) - 2.0;
  const double base = 0.5;
  const float* centre = f.hdr.at(kCentred / 2, kCentred / 2);
  for (int ch = 0; ch < 3; ++ch) {
    const double expected = 0.02 * base + (base * NoL + 0.04 * std::pow(NoH, shininess)) * color[ch];
    CHECK(centre[ch] == doctest::Approx(expected).epsilon(1e-4));
  }
}

TEST_CASE("physical exposure: a white floor under a 100000 lux sun at EV100 15 reads f E / (1.2 2^15)") {
  PBR_REQUIRE_GL();
  const TempDir dir;
  const std::string scenePath = dir.write("sun.json", R"({
    "camera": {"position": [0, 5, 0], "target": [0, 0, 0], "up": [0, 0, -1], "fov_y_deg": 45, "ev100": 15},
    "objects": [{"shape": "plane", "transform": {"scale": 40},
                 "material": {"base_color": 1, "roughness": 1, "metalness": 0}}],
    "lights": [{"type": "directional", "direction": [0, -1, 0], "illuminance_lux": 100000}]
  })");
  const pbr::Scene scene = pbr::loadSceneFile(scenePath);
  const double E = 1e5, exposure = 1.0 / (1.2 * std::exp2(15.0));
  CHECK(scene.displayExposure() == doctest::Approx(exposure).epsilon(1e-6));

  // The floor's BRDF at normal incidence (V = L = N), from the reference's terms: Lambert weighted by 1 - F plus
  // GGX's specular at roughness 1. Pure Lambert would give E / pi x exposure = 0.81; Fresnel takes 3% of it.
  const dvec3 N(0.0, 1.0, 0.0);
  const double f = ref::evaluateBrdf(N, N, N, {dvec3(1.0), 1.0, 0.0}, ref::BrdfForms{}).sum().x;
  const double predicted = f * E * exposure;
  MESSAGE("f = " << f << " (1/pi = " << 1.0 / M_PI << "), predicted value before tone mapping " << predicted);
  CHECK(predicted == doctest::Approx(E / M_PI * exposure).epsilon(0.04));

  const pbr::ShaderLibrary shaders;
  pbr::FrameOptions options;
  options.exposure = scene.displayExposure();
  const pbr::RenderedFrames frame = pbr::renderOffscreen(shaders, scene, {kCentred, kCentred}, options, 1);
  const float* centre = frame.hdr.at(kCentred / 2, kCentred / 2);
  for (int ch = 0; ch < 3; ++ch) CHECK(centre[ch] * exposure == doctest::Approx(predicted).epsilon(0.01));

  // The command applies the camera's EV100, and --ev100 replaces it: the centre pixel is sRGB(ACES(value)).
  const auto centreCode = [&](const std::vector<std::string>& extra) {
    std::vector<std::string> args = {"render", "--scene", scenePath, "--size", "33x33", "--frames", "1",
                                     "--warmup", "0", "--out", dir.file("sun.png")};
    args.insert(args.end(), extra.begin(), extra.end());
    const pbr::test::PbrRun run = pbr::test::runPbr(dir, args);
    REQUIRE(run.exitCode == 0);
    const pbr::ImageRgba8 png = pbr::readPng(dir.file("sun.png"));
    return int(png.pixels[(size_t(kCentred / 2) * png.width + kCentred / 2) * 4]);
  };
  const auto expectedCode = [&](double value) { return srgb8(ref::acesHill(dvec3(value)).x); };
  CHECK(std::abs(centreCode({}) - expectedCode(predicted)) <= 1);
  CHECK(std::abs(centreCode({"--ev100", "16"}) - expectedCode(predicted / 2.0)) <= 1);
  CHECK(std::abs(centreCode({"--ev100", "16", "--exposure", "4"}) - expectedCode(predicted * 2.0)) <= 1);
}
