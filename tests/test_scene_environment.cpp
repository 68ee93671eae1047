// The environment field of a scene file: a sky or an image file resolved against the scene file's folder, and the
// one-line error of each malformed value.
#include <doctest/doctest.h>

#include <filesystem>
#include <string>

#include <glm/vec3.hpp>

#include "core/scene_json.hpp"
#include "tests/cli_util.hpp"

using namespace pbr;
using test::TempDir;

namespace {

std::string loadError(const std::string& path) {
  try {
    loadSceneFile(path);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(loaded)";
}

}  // namespace

TEST_CASE("ibl render: the scene file's environment field, its paths and its errors") {
  const TempDir dir;
  const std::string head = R"({"camera": {"position": [0, 0, 5], "target": [0, 0, 0]}, "environment": )";
  auto scene = [&](const std::string& name, const std::string& environment) {
    return dir.write(name, head + environment + "}\n");
  };

  const Scene sky = loadSceneFile(
      scene("sky.json", R"({"sky": {"zenith": 0.5, "sun_radiance": 0}, "intensity": 2, "rotation_deg": 30})"));
  REQUIRE(sky.environment);
  CHECK(sky.environment->file.empty());
  CHECK(sky.environment->sky.zenith == glm::vec3(0.5f));
  CHECK(sky.environment->sky.sunRadiance == glm::vec3(0.0f));
  CHECK(sky.environment->sky.horizon == SkyParams{}.horizon);
  CHECK(sky.environment->intensity == 2.0f);
  CHECK(sky.environment->rotationDeg == 30.0f);
  const std::string none = dir.write("none.json", R"({"camera": {"position": [0, 0, 5], "target": [0, 0, 0]}})");
  CHECK_FALSE(loadSceneFile(none).environment);

  // A relative file resolves against the scene file's folder.
  dir.write("maps/env.hdr", "not checked until rendered");
  const Scene file = loadSceneFile(scene("file.json", R"({"file": "maps/env.hdr"})"));
  REQUIRE(file.environment);
  CHECK(std::filesystem::equivalent(file.environment->file, dir.path() / "maps" / "env.hdr"));

  struct Bad {
    const char* environment;
    std::string error;
  };
  const Bad cases[] = {
      {"{}", R"(environment: expected a "file" or a "sky" field)"},
      {R"({"file": "maps/env.hdr", "sky": {}})", R"(environment: expected "file" or "sky", got both)"},
      {R"({"file": "no/such.hdr"})", "environment.file: " + (dir.path() / "no" / "such.hdr").string() + ": cannot open: No such file"},
      {R"({"file": 3})", "environment.file: expected a string, got 3"},
      {R"({"sky": true})", "environment.sky: expected an object, got true"},
      {R"({"sky": {"zenith": [1, -1, 0]}})", "environment.sky.zenith[1]: expected a finite number >= 0, got -1"},
      {R"({"sky": {"sun_direction": [0, 0, 0]}})", "environment.sky.sun_direction: expected a non-zero direction"},
      {R"({"sky": {"sun_angular_radius_deg": 0}})",
       "environment.sky.sun_angular_radius_deg: expected a number in (0, 90), got 0"},
      {R"({"sky": {}, "intensity": -1})", "environment.intensity: expected a finite number >= 0, got -1"},
      {R"({"sky": {}, "rotation_deg": "east"})", R"(environment.rotation_deg: expected a finite number, got "east")"},
      {"5", "environment: expected an object, got 5"},
  };
  for (const Bad& bad : cases) {
    const std::string path = scene("bad.json", bad.environment);
    const std::string message = loadError(path);
    CAPTURE(message);
    CHECK(message.rfind(path + ": ", 0) == 0);
    CHECK(message.find('\n') == std::string::npos);
    CHECK(message.find(bad.error) != std::string::npos);
  }
}
