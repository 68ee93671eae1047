// The environment field of a scene file: a sky or an image file resolved against the scene file's folder, "none",
// the one-line error of each malformed value, and the procedural sky that glTF models get when the file is silent.
#include <doctest/doctest.h>

#include <filesystem>
#include <string>

#include <glm/vec3.hpp>

#include "app/accuracy/accuracy_variants.hpp"
#include "core/scene/assets.hpp"
#include "core/scene/scene_json.hpp"
#include "tests/cli_util.hpp"

using namespace pbr;
using test::TempDir;

namespace {

// The note of a loader that lit glTF models by the sky because the file named no environment; empty when none.
std::string skyNote(const Scene& scene) {
  for (const std::string& note : scene.notes) {
    if (note.find("procedural sky") != std::string::npos) return note;
  }
  return {};
}

// The environment a scene gets by default: the sky of SkyParams, as `--environment sky` sets it.
void checkDefaultSky(const Scene& scene) {
  REQUIRE(scene.environment);
  CHECK(scene.environment->file.empty());
  CHECK(scene.environment->sky.zenith == SkyParams{}.zenith);
  CHECK(scene.environment->sky.sunRadiance == SkyParams{}.sunRadiance);
  CHECK(scene.environment->intensity == 1.0f);
  CHECK(scene.environment->rotationDeg == 0.0f);
}

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
      {R"("sky")", R"(environment: expected "none" or an object with a "file" or a "sky" field, got "sky")"},
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

TEST_CASE("scene environment: glTF models in a file silent about an environment are lit by the sky, and it is said") {
  const std::string box = assetPath("BoxTextured/glTF-Embedded/BoxTextured.gltf");
  const Scene alone = loadSceneFile(box);
  checkDefaultSky(alone);
  CHECK(skyNote(alone) == "no environment in the file: lit by the procedural sky (--environment none turns it off)");
  const Scene measured = loadSceneFile(box, -1, {}, false, DefaultEnvironment::None);
  CHECK_FALSE(measured.environment);
  CHECK(skyNote(measured).empty());

  const TempDir dir;
  const std::string camera = R"("camera": {"position": [0, 0, 5], "target": [0, 0, 0]})";
  auto scene = [&](const std::string& name, const std::string& fields) {
    return loadSceneFile(dir.write(name, "{" + camera + fields + "}\n"));
  };
  const std::string model = R"(, "objects": [{"gltf": "asset:BoxTextured/glTF-Embedded/BoxTextured.gltf"}])";
  const std::string shape = R"(, "objects": [{"shape": "sphere"}])";

  const Scene silent = scene("silent.json", model);
  checkDefaultSky(silent);
  CHECK(skyNote(silent).find(R"("environment": "none" in the file or --environment none)") != std::string::npos);
  const Scene none = scene("none.json", model + R"(, "environment": "none")");
  CHECK_FALSE(none.environment);
  CHECK(none.notes.empty());
  const Scene own = scene("own.json", model + R"(, "environment": {"sky": {"zenith": 0.5}, "intensity": 3})");
  REQUIRE(own.environment);
  CHECK(own.environment->sky.zenith == glm::vec3(0.5f));
  CHECK(own.environment->intensity == 3.0f);
  CHECK(own.notes.empty());

  // Scenes of shapes alone render as they always have.
  const Scene shapes = scene("shapes.json", shape);
  CHECK_FALSE(shapes.environment);
  CHECK(shapes.notes.empty());
  CHECK_FALSE(scene("shapes_none.json", shape + R"(, "environment": "none")").environment);

  // The accuracy command compares with the reference, which has no image-based lighting.
  CHECK_FALSE(loadAccuracyScene(dir.file("silent.json")).scene.environment);
}
