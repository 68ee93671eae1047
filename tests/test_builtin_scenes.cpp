// Built-in scenes: each is its scenes/*.json file, and the command-line parameters act on the loaded scene.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/vector_relational.hpp>

#include "core/scene/builtin_scenes.hpp"
#include "core/scene/scene_json.hpp"
#include "tests/cli_util.hpp"

namespace fs = std::filesystem;
using pbr::test::TempDir;

namespace {

const fs::path kSceneFolder = fs::path(PBR_SOURCE_DIR) / "scenes";

pbr::SceneParams withLights(int count) {
  pbr::SceneParams p;
  p.lights = count;
  return p;
}

pbr::SceneParams atViewAngle(float degrees) {
  pbr::SceneParams p;
  p.viewAngleDeg = degrees;
  return p;
}

// Bit for bit: a parameter must reproduce what the file holds exactly, or frames change.
bool sameBits(const pbr::PointLight& a, const pbr::PointLight& b) {
  return std::memcmp(&a.position, &b.position, sizeof a.position) == 0 && a.radius == b.radius &&
         std::memcmp(&a.color, &b.color, sizeof a.color) == 0 && a.luminousPower == b.luminousPower;
}

void checkSameLights(const std::vector<pbr::PointLight>& got, const std::vector<pbr::PointLight>& want) {
  REQUIRE(got.size() == want.size());
  for (size_t i = 0; i < got.size(); ++i) {
    CAPTURE(i);
    CHECK(sameBits(got[i], want[i]));
  }
}

void checkNear(const glm::vec3& got, const glm::dvec3& want) {
  for (int i = 0; i < 3; ++i) CHECK(got[i] == doctest::Approx(want[i]).epsilon(1e-6));
}

// How many lights lie outside the box [lo, hi] or have another radius than `radius`.
size_t lightsOutside(const std::vector<pbr::PointLight>& lights, const glm::vec3& lo, const glm::vec3& hi,
                     float radius) {
  size_t n = 0;
  for (const pbr::PointLight& l : lights) {
    const bool inside = glm::all(glm::greaterThanEqual(l.position, lo)) && glm::all(glm::lessThanEqual(l.position, hi));
    n += inside && l.radius == radius ? 0 : 1;
  }
  return n;
}

// Sets an environment variable for one scope, then restores it.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const std::string& value) : name_(name) {
    const char* previous = std::getenv(name);
    if (previous) saved_ = previous;
    ::setenv(name, value.c_str(), 1);
  }
  ~ScopedEnv() {
    if (saved_) {
      ::setenv(name_, saved_->c_str(), 1);
    } else {
      ::unsetenv(name_);
    }
  }
  ScopedEnv(const ScopedEnv&) = delete;
  ScopedEnv& operator=(const ScopedEnv&) = delete;

 private:
  const char* name_;
  std::optional<std::string> saved_;
};

}  // namespace

TEST_CASE("built-in scenes: each name is a file of scenes/ that loads as that scene, and each file is a built-in") {
  for (const std::string& name : pbr::builtinSceneNames()) {
    CAPTURE(name);
    REQUIRE(fs::is_regular_file(kSceneFolder / (name + ".json")));
    const pbr::Scene scene = pbr::makeBuiltinScene(name);
    CHECK(scene.name == name);
    CHECK(!scene.objects.empty());
    CHECK(!scene.lights.empty());
    CHECK(scene.lights.size() == pbr::loadSceneFile((kSceneFolder / (name + ".json")).string()).lights.size());
    // What bench and accuracy measure: lit by their lights alone, whether or not they place glTF models.
    CHECK_FALSE(scene.environment);
    CHECK(scene.notes.empty());
  }
  for (const fs::directory_entry& e : fs::directory_iterator(kSceneFolder)) {
    if (e.path().extension() != ".json") continue;
    CAPTURE(e.path());
    CHECK(pbr::isBuiltinScene(e.path().stem().string()));
  }
  CHECK_THROWS_WITH_AS(
      pbr::makeBuiltinScene("nope"),
      "unknown scene 'nope' (built-in scenes: default, sphere-grid, light-wall, fresnel-floor, stress, helmet, "
      "helmet-grid, many-lights, shadow-trio, transparency, material-specular, material-clearcoat, material-sheen, "
      "material-transmission, materials)",
      pbr::SceneError);
  CHECK_THROWS_WITH_AS(pbr::makeBuiltinScene("default", withLights(-1)), "default: light count must be >= 0",
                       pbr::SceneError);
}

TEST_CASE("built-in scenes: --lights N sets random_lights.count, drawing the same lights in the same order") {
  for (const char* name : {"default", "stress"}) {
    CAPTURE(name);
    const pbr::Scene file = pbr::makeBuiltinScene(name);
    const pbr::Scene seven = pbr::makeBuiltinScene(name, withLights(7));
    REQUIRE(file.lights.size() > 7);
    checkSameLights(seven.lights, {file.lights.begin(), file.lights.begin() + 7});
    CHECK(pbr::makeBuiltinScene(name, withLights(0)).lights.empty());
  }
}

TEST_CASE("built-in scenes: --lights N on the scenes that list their lights") {
  SUBCASE("sphere-grid: N random lights in front of the grid replace the four corner lights") {
    const pbr::Scene scene = pbr::makeBuiltinScene("sphere-grid", withLights(7));
    REQUIRE(scene.lights.size() == 7);
    for (const pbr::PointLight& l : scene.lights) {
      CHECK(l.position.z >= 1.0f);
      CHECK(l.position.z <= 6.0f);
      CHECK(l.luminousPower >= 500.0f / 7);
      CHECK(l.luminousPower <= 2000.0f / 7);
    }
    CHECK(pbr::makeBuiltinScene("sphere-grid", withLights(0)).lights.empty());
  }
  SUBCASE("light-wall: N copies of the file's light") {
    const pbr::Scene file = pbr::makeBuiltinScene("light-wall");
    REQUIRE(file.lights.size() == 1);
    checkSameLights(pbr::makeBuiltinScene("light-wall", withLights(5)).lights,
                    std::vector<pbr::PointLight>(5, file.lights[0]));
  }
  SUBCASE("fresnel-floor: one light, and no other count") {
    CHECK(pbr::makeBuiltinScene("fresnel-floor", withLights(1)).lights.size() == 1);
    CHECK_THROWS_WITH_AS(pbr::makeBuiltinScene("fresnel-floor", withLights(2)),
                         "fresnel-floor: the scene has exactly one light", pbr::SceneError);
  }
  SUBCASE("helmet: a ring of N lights of the same total power, which at the file's count is the file's ring") {
    const pbr::Scene file = pbr::makeBuiltinScene("helmet");
    checkSameLights(pbr::makeBuiltinScene("helmet", withLights(static_cast<int>(file.lights.size()))).lights,
                    file.lights);
    const pbr::Scene three = pbr::makeBuiltinScene("helmet", withLights(3));
    REQUIRE(three.lights.size() == 3);
    for (const pbr::PointLight& l : three.lights) CHECK(l.luminousPower == doctest::Approx(1500.0f / 3));
  }
}

TEST_CASE("built-in scenes: helmet-grid is nine DamagedHelmets sharing one mesh and its textures, 8192 lights") {
  const pbr::Scene scene = pbr::makeBuiltinScene("helmet-grid");
  CHECK(scene.meshes.size() == 1);
  CHECK(scene.textures.size() == 5);
  REQUIRE(scene.objects.size() == 9);
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    CAPTURE(i);
    // Listed x-major, x and z in {-3, 0, 3}, at y = -0.5 and half size.
    const glm::mat4& m = scene.objects[i].transform;
    const glm::vec3 origin(m * glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    checkNear(origin, {-3.0 + 3.0 * double(i / 3), -0.5, -3.0 + 3.0 * double(i % 3)});
    CHECK(glm::length(glm::vec3(m[0])) == doctest::Approx(0.5));
    CHECK(scene.objects[i].mesh == 0);
  }
  REQUIRE(scene.lights.size() == 8192);
  CHECK(lightsOutside(scene.lights, {-3.0f, -4.0f, -3.0f}, {3.0f, 2.0f, 3.0f}, 4.7f) == 0);
  // --lights N sets random_lights.count.
  checkSameLights(pbr::makeBuiltinScene("helmet-grid", withLights(7)).lights,
                  {scene.lights.begin(), scene.lights.begin() + 7});
}

TEST_CASE("built-in scenes: many-lights spreads 65536 lights over its floor, and --lights takes up to 2^20") {
  const pbr::Scene scene = pbr::makeBuiltinScene("many-lights");
  REQUIRE(scene.lights.size() == 65536);
  CHECK(lightsOutside(scene.lights, {-100.0f, 0.3f, -100.0f}, {100.0f, 2.0f, 100.0f}, 3.0f) == 0);
  // The command line's largest count, 1,048,576, draws the same lights first.
  const pbr::Scene most = pbr::makeBuiltinScene("many-lights", withLights(1 << 20));
  REQUIRE(most.lights.size() == size_t(1) << 20);
  checkSameLights({most.lights.begin(), most.lights.begin() + 100}, {scene.lights.begin(), scene.lights.begin() + 100});
}

TEST_CASE("built-in scenes: --view-angle puts fresnel-floor's camera and mirrored light at that angle") {
  const pbr::Scene file = pbr::makeBuiltinScene("fresnel-floor");
  SUBCASE("at the file's 40 degrees, the file's camera and light to the bit") {
    const pbr::Scene forty = pbr::makeBuiltinScene("fresnel-floor", atViewAngle(40.0f));
    CHECK(std::memcmp(&forty.camera, &file.camera, sizeof file.camera) == 0);
    checkSameLights(forty.lights, file.lights);
  }
  SUBCASE("at 75 degrees, 6 units from the floor's centre, the light 1.5 units along the mirror direction") {
    const pbr::Scene scene = pbr::makeBuiltinScene("fresnel-floor", atViewAngle(75.0f));
    const double theta = 75.0 * glm::pi<double>() / 180.0;
    checkNear(scene.camera.position, 6.0 * glm::dvec3(0.0, std::cos(theta), std::sin(theta)));
    checkNear(scene.lights.at(0).position, 1.5 * glm::dvec3(0.0, std::cos(theta), -std::sin(theta)));
    const glm::vec3 view = glm::normalize(scene.camera.position - scene.camera.target);
    CHECK(std::acos(view.y) * 180.0 / glm::pi<double>() == doctest::Approx(75.0).epsilon(1e-5));
    CHECK(scene.camera.up == glm::vec3(0.0f, 1.0f, 0.0f));
    CHECK(scene.camera.target == file.camera.target);
  }
  SUBCASE("looking straight down, up is -z, not parallel to the view") {
    const pbr::Scene scene = pbr::makeBuiltinScene("fresnel-floor", atViewAngle(0.5f));
    CHECK(scene.camera.up == glm::vec3(0.0f, 0.0f, -1.0f));
  }
  SUBCASE("outside [0, 89] it is refused") {
    CHECK_THROWS_WITH_AS(pbr::makeBuiltinScene("fresnel-floor", atViewAngle(90.0f)),
                         "fresnel-floor: view angle must be in [0, 89] degrees (got 90.000000)", pbr::SceneError);
  }
}

TEST_CASE("built-in scenes: PBR_SCENE_DIR moves their folder, and a missing file is one line naming its path") {
  const TempDir dir;
  dir.write("light-wall.json", R"({"camera": {"position": [0, 0, 4], "target": [0, 0, 0]}, "exposure": 3,
    "lights": [{"position": [0, 0, 1], "luminous_power": 50, "radius": 10}]})");
  const ScopedEnv env("PBR_SCENE_DIR", dir.path().string());
  CHECK(pbr::builtinSceneDir() == dir.path().string());
  CHECK(pbr::makeBuiltinScene("light-wall").exposure == 3.0f);
  const std::string expected = dir.file("default.json") + ": ";
  try {
    pbr::makeBuiltinScene("default");
    FAIL("a missing built-in scene file loaded");
  } catch (const pbr::SceneError& e) {
    const std::string message = e.what();
    CHECK(message.rfind(expected, 0) == 0);
    CHECK(message.find("PBR_SCENE_DIR") != std::string::npos);
    CHECK(message.find('\n') == std::string::npos);
  }
}
