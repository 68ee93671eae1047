// The procedural sky a glTF model given alone gets: a mirror shows the sky's radiance along the reflected view ray,
// where without it a metal is near black; `pbr render` says so, and --environment decides instead where given.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "core/scene/image.hpp"
#include "core/scene/scene_json.hpp"
#include "tests/cli_util.hpp"
#include "tests/gl_test_context.hpp"
#include "tests/gltf_builder.hpp"
#include "tests/render_util.hpp"

using pbr::test::TempDir;

namespace {

// Odd: the middle pixel's ray passes through the camera's target, the centre of the model's bounds.
constexpr int kSize = 33;

// A 2 x 2 mirror facing +Z: white metal of roughness 0, whose reflectance is 1 at every angle.
std::string mirrorModel(const TempDir& dir) {
  pbr::test::GltfBuilder b;
  pbr::test::QuadSpec quad;
  quad.material = b.addMaterial({{"pbrMetallicRoughness",
                                  {{"baseColorFactor", {1.0, 1.0, 1.0, 1.0}},
                                   {"metallicFactor", 1.0},
                                   {"roughnessFactor", 0.0}}}});
  b.addRootNode({{"mesh", pbr::test::addQuad(b, quad)}});
  return b.writeGltf(dir.path(), "mirror");
}

// The sky's radiance along `d`, away from the sun: its gradient (shaders/ibl/sky.glsl).
glm::vec3 skyGradient(const pbr::SkyParams& sky, const glm::vec3& d) {
  return d.y >= 0.0f ? glm::mix(sky.horizon, sky.zenith, std::sqrt(d.y))
                     : glm::mix(sky.horizon, sky.ground, std::sqrt(-d.y));
}

// Linear radiance at the middle pixel.
glm::vec3 centreRadiance(const pbr::Scene& scene) {
  const pbr::test::RenderedFrame frame = pbr::test::renderScene(scene, {kSize, kSize}, pbr::FrameOptions{}, 1);
  const float* p = frame.hdr.at(kSize / 2, kSize / 2);
  return {p[0], p[1], p[2]};
}

float maxRelative(const glm::vec3& got, const glm::vec3& want) {
  const glm::vec3 d = glm::abs(got - want) / want;
  return std::max({d.x, d.y, d.z});
}

// Green of the middle pixel of a PNG `pbr render` wrote.
int centreGreen(const std::string& png) {
  const pbr::ImageRgba8 image = pbr::readPng(png);
  return image.pixels[(static_cast<size_t>(image.height / 2) * image.width + image.width / 2) * 4 + 1];
}

}  // namespace

TEST_CASE("default environment: a mirror given alone shows the sky it reflects, and is near black without it") {
  PBR_REQUIRE_GL();
  const TempDir dir;
  const std::string model = mirrorModel(dir);
  const pbr::Scene lit = pbr::loadSceneFile(model);
  REQUIRE(lit.environment);
  // The framing looks down on the mirror's centre, so the reflected ray leaves below the horizon, opposite the sun.
  const glm::vec3 view = glm::normalize(lit.camera.target - lit.camera.position);
  const glm::vec3 reflected = glm::reflect(view, glm::vec3(0.0f, 0.0f, 1.0f));
  const glm::vec3 expected = skyGradient(lit.environment->sky, reflected);
  const glm::vec3 got = centreRadiance(lit);
  // The split sum is exact for a mirror of reflectance 1 but for the rounding of the DFG table, the cube's texels
  // and fp16: measured 0.08% off on llvmpipe.
  MESSAGE("mirror centre " << got.x << ", " << got.y << ", " << got.z << "; sky along the reflection " << expected.x
                           << ", " << expected.y << ", " << expected.z);
  CHECK(maxRelative(got, expected) < 0.01f);

  // Without it the rig's three lights are points that the mirror reflects nowhere near its centre: it shows the
  // uniform ambient radiance alone, 0.03, about a tenth of the sky's.
  const pbr::Scene unlit = pbr::loadSceneFile(model, -1, {}, false, pbr::DefaultEnvironment::None);
  REQUIRE_FALSE(unlit.environment);
  const glm::vec3 dark = centreRadiance(unlit);
  MESSAGE("without an environment " << dark.x << ", " << dark.y << ", " << dark.z);
  CHECK(maxRelative(dark, unlit.ambient) < 0.01f);
  CHECK(std::min({got.x, got.y, got.z}) > 5.0f * std::max({dark.x, dark.y, dark.z}));
}

TEST_CASE("default environment: pbr render notes the sky of a model alone, and --environment decides where given") {
  PBR_REQUIRE_GL();
  const TempDir dir;
  const std::string model = mirrorModel(dir);
  auto render = [&](const std::string& png, const std::vector<std::string>& extra) {
    std::vector<std::string> args = {"render", "--scene", model, "--size", "33x33", "--frames", "1", "--warmup", "0",
                                     "--out", dir.file(png)};
    args.insert(args.end(), extra.begin(), extra.end());
    const pbr::test::PbrRun run = pbr::test::runPbr(dir, args);
    CAPTURE(run.err);
    CHECK(run.exitCode == 0);
    return run.out;
  };
  const std::string note =
      "note: no environment in the file: lit by the procedural sky (--environment none turns it off)\n";
  const std::string lit = render("lit.png", {});
  CHECK(lit.find(note) != std::string::npos);
  CHECK(lit.find("environment: procedural sky") != std::string::npos);
  // Asked for, the sky needs no note; refused, there is none to speak of.
  const std::string asked = render("asked.png", {"--environment", "sky"});
  CHECK(asked.find(note) == std::string::npos);
  CHECK(asked.find("environment: procedural sky") != std::string::npos);
  const std::string none = render("none.png", {"--environment", "none"});
  CHECK(none.find("procedural sky") == std::string::npos);
  CHECK(none.find("note: the file places no lights") != std::string::npos);

  const int litGreen = centreGreen(dir.file("lit.png")), darkGreen = centreGreen(dir.file("none.png"));
  MESSAGE("centre green: " << litGreen << " under the sky, " << darkGreen << " without");
  CHECK(centreGreen(dir.file("asked.png")) == litGreen);
  CHECK(litGreen > 100);
  CHECK(darkGreen < 40);
}
