// Scene files that must not be rendered: each error is one line naming the file, the JSON path and what was
// expected.
#include <doctest/doctest.h>

#include <functional>
#include <string>
#include <vector>

#include "core/scene/scene_json.hpp"
#include "tests/cli_util.hpp"

using pbr::test::TempDir;

namespace {

// Valid as written; each case below changes one snippet of it.
const std::string kValid = R"({
  "camera": {"position": [0, 2, 6], "target": [0, 0, 0], "fov_y_deg": 50, "near": 0.1, "far": 100},
  "exposure": 1,
  "ambient": 0.02,
  "objects": [
    {"shape": "sphere", "transform": {"translate": [0, 1, 0], "scale": 2}, "material": {"base_color": [0.8, 0.2, 0.2], "roughness": 0.4, "metalness": 0}}
  ],
  "lights": [
    {"position": [1, 3, 1], "color": [1, 1, 1], "luminous_power": 100, "radius": 5}
  ],
  "random_lights": {"count": 4, "seed": 2, "bounds": [[-1, 0, -1], [1, 2, 1]], "radius": [1, 2], "luminous_power": [10, 20]}
}
)";

struct BadCase {
  const char* from;  // a snippet of kValid
  const char* to;    // what replaces it
  const char* error;  // expected in the message, after "<file>: "
};

const BadCase kBadCases[] = {
    // wrong types
    {R"("exposure": 1)", R"("exposure": "bright")", R"(exposure: expected a number in [0, 1e+06], got "bright")"},
    // An exposure that would carry the brightest radiance out of float range in the tone curve: a black frame.
    {R"("exposure": 1)", R"("exposure": 1e25)", R"(exposure: expected a number in [0, 1e+06], got 1e+25)"},
    {R"("translate": [0, 1, 0])", R"("translate": [0, 1])", "objects[0].transform.translate: expected an array of 3 numbers, got [0,1]"},
    {R"("color": [1, 1, 1])", R"("color": [1, "x", 1])", R"(lights[0].color[1]: expected a finite number >= 0, got "x")"},
    {R"("camera": {"position": [0, 2, 6], "target": [0, 0, 0], "fov_y_deg": 50, "near": 0.1, "far": 100})",
     R"("camera": 5)", "camera: expected an object, got 5"},
    {R"("objects": [)", R"("objects": {"shape": "box"}, "unused": [)", "objects: expected an array, got {\"shape\":\"box\"}"},
    {R"("count": 4)", R"("count": 4.5)", "random_lights.count: expected an integer in [0, 1048576], got 4.5"},
    {R"("count": 4)", R"("count": -4)", "random_lights.count: expected an integer in [0, 1048576], got -4"},
    // missing required fields
    {R"(, "radius": 5)", "", "lights[0].radius: expected a number in [0, 1e+12], but the field is missing"},
    {R"(, "target": [0, 0, 0])", "", "camera.target: expected an array of 3 numbers, but the field is missing"},
    {R"("shape": "sphere", )", "", R"(objects[0]: expected a "shape" or a "gltf" field)"},
    {R"("luminous_power": 100, )", "", "lights[0]: expected luminous_power (lm) or intensity_cd (cd), got neither"},
    // values out of range
    {R"("radius": 5)", R"("radius": -1)", "lights[0].radius: expected a number in [0, 1e+12], got -1"},
    {R"("radius": 5)", R"("radius": 1e999)", "lights[0].radius: expected a finite number, got 1e999"},
    {R"("luminous_power": 100)", R"("luminous_power": 1e39)", "lights[0].luminous_power: expected a finite number >= 0, got 1e+39"},
    {R"("roughness": 0.4)", R"("roughness": 1.5)", "objects[0].material.roughness: expected a number in [0, 1], got 1.5"},
    {R"("metalness": 0)", R"("metalness": -0.1)", "objects[0].material.metalness: expected a number in [0, 1], got -0.1"},
    {R"("base_color": [0.8, 0.2, 0.2])", R"("base_color": [0.8, 1.2, 0.2])", "objects[0].material.base_color[1]: expected a number in [0, 1], got 1.2"},
    {R"("metalness": 0)", R"("metalness": 0, "alpha": 1.5)", "objects[0].material.alpha: expected a number in [0, 1], got 1.5"},
    {R"("metalness": 0)", R"("metalness": 0, "alpha": -0.5)", "objects[0].material.alpha: expected a number in [0, 1], got -0.5"},
    {R"("metalness": 0)", R"("metalness": 0, "alpha_cutoff": -0.1)", "objects[0].material.alpha_cutoff: expected a finite number >= 0, got -0.1"},
    {R"("fov_y_deg": 50)", R"("fov_y_deg": 0)", "camera.fov_y_deg: expected a number in (0, 180), got 0"},
    {R"("fov_y_deg": 50)", R"("fov_y_deg": 180)", "camera.fov_y_deg: expected a number in (0, 180), got 180"},
    {R"("near": 0.1)", R"("near": 0)", "camera.near: expected a finite number > 0, got 0"},
    {R"("far": 100)", R"("far": 0.1)", "camera.far: expected a finite number > camera.near (0.1), got 0.1"},
    {R"("far": 100)", R"("far": 0.05)", "camera.far: expected a finite number > camera.near (0.1), got 0.05"},
    {R"("scale": 2)", R"("scale": 0)", "objects[0].transform.scale: expected a number in [1e-09, 1e+12], got 0"},
    {R"("scale": 2)", R"("scale": [1, -1, 1])", "objects[0].transform.scale[1]: expected a number in [1e-09, 1e+12], got -1"},
    // contradictions
    {R"("target": [0, 0, 0])", R"("target": [0, 2, 6])", "camera.target: expected a point other than camera.position"},
    {R"("fov_y_deg": 50)", R"("up": [0, -1, -3], "fov_y_deg": 50)", "camera.up: expected a direction not parallel to target - position"},
    {R"("shape": "sphere")", R"("shape": "cone")", R"(objects[0].shape: expected "plane", "box" or "sphere", got "cone")"},
    {R"("shape": "sphere")", R"("shape": "sphere", "gltf": "m.gltf")", R"(objects[0]: expected "shape" or "gltf", got both)"},
    {R"("shape": "sphere")", R"("gltf": "m.gltf")", "objects[0].material: a glTF object takes its materials from its file"},
    {R"("luminous_power": 100)", R"("luminous_power": 100, "intensity_cd": 8)", "lights[0]: expected luminous_power or intensity_cd, got both"},
    {"[[-1, 0, -1], [1, 2, 1]]", "[[1, 0, -1], [-1, 2, 1]]", "random_lights.bounds: expected [[min x, y, z], [max x, y, z]] with min <= max, got [[1,0,-1],[-1,2,1]]"},
    {"[[-1, 0, -1], [1, 2, 1]]", "[[-1, 0, -1]]", "random_lights.bounds: expected [[min x, y, z], [max x, y, z]] with min <= max, got [[-1,0,-1]]"},
    {R"("radius": [1, 2])", R"("radius": [2, 1])", "random_lights.radius: expected [lo, hi], lo <= hi, each a number in [0, 1e+12], got [2,1]"},
    {R"("metalness": 0)", R"("metalness": 0, "alpha_mode": "translucent")", R"(objects[0].material.alpha_mode: expected "opaque" (the default), "mask" or "blend", got "translucent")"},
    {R"("metalness": 0)", R"("metalness": 0, "alpha_mode": 2)", "objects[0].material.alpha_mode: expected a string, got 2"},
    {R"({"position": [1, 3, 1])", R"({"type": "area", "position": [1, 3, 1])", R"(lights[0].type: expected "point" (the default), "spot" or "directional", got "area")"},
    {R"({"position": [1, 3, 1])", R"({"type": "spot", "direction": [0, -1, 0], "outer_angle_deg": 30, "inner_angle_deg": 40, "position": [1, 3, 1])", "lights[0].inner_angle_deg: expected a number in [0, 30], got 40"},
    {R"({"position": [1, 3, 1])", R"({"type": "spot", "direction": [0, 0, 0], "position": [1, 3, 1])", "lights[0].direction: expected a non-zero direction"},
    {R"({"position": [1, 3, 1], "color": [1, 1, 1], "luminous_power": 100, "radius": 5})", R"({"type": "directional", "direction": [0, 0, 0], "illuminance_lux": 5})", "lights[0].direction: expected a non-zero direction"},
    {R"({"position": [1, 3, 1], "color": [1, 1, 1], "luminous_power": 100, "radius": 5})", R"({"type": "directional", "direction": [0, -1, 0]})", "lights[0].illuminance_lux: expected a number in [0, 1e+12], but the field is missing"},
    {R"("fov_y_deg": 50)", R"("fov_y_deg": 50, "ev100": 12, "iso": 100)", "camera: expected ev100 or aperture, shutter_s and iso, got both"},
    {R"("fov_y_deg": 50)", R"("fov_y_deg": 50, "aperture": 8, "iso": 100)", "camera.shutter_s: expected a finite number > 0, but the field is missing"},
    {R"("fov_y_deg": 50)", R"("fov_y_deg": 50, "ev100": 99)", "camera.ev100: expected a number in [-64, 64], got 99"},
    // files the scene names
    {R"("metalness": 0})", R"("metalness": 0, "base_color_texture": "no/such.png"})", "objects[0].material.base_color_texture: "},
    {R"({"shape": "sphere", "transform": {"translate": [0, 1, 0], "scale": 2}, "material": {"base_color": [0.8, 0.2, 0.2], "roughness": 0.4, "metalness": 0}})",
     R"({"gltf": "models/none.gltf"})", ": cannot open: No such file or directory"},
    // JSON syntax: line and column of the offending character
    {R"("exposure": 1,)", R"("exposure": 1,,)", ":3:17: JSON syntax error: "},
    {"[10, 20]}\n}\n", "[10, 20]}\n", ":12:1: JSON syntax error: "},
};

void checkOneLineError(const std::string& path, const std::function<void()>& load, const std::string& expected) {
  try {
    load();
    FAIL("accepted: expected \"" << expected << "\"");
  } catch (const pbr::SceneError& e) {
    const std::string message = e.what();
    CAPTURE(message);
    CHECK(message.rfind(path, 0) == 0);  // names the file first
    CHECK(message.find('\n') == std::string::npos);
    CHECK(message.find(expected) != std::string::npos);
  }
}

}  // namespace

TEST_CASE("scene file errors: the unchanged file loads") {
  const TempDir dir;
  CHECK(pbr::loadSceneFile(dir.write("scene.json", kValid)).lights.size() == 1 + 4);
}

TEST_CASE("scene file errors: each rejected field names the file, its JSON path and what was expected") {
  const TempDir dir;
  int n = 0;
  for (const BadCase& c : kBadCases) {
    const std::string change = c.to;
    CAPTURE(change);
    std::string text = kValid;
    const size_t at = text.find(c.from);
    REQUIRE_MESSAGE(at != std::string::npos, "snippet not in the valid file: " << c.from);
    text.replace(at, std::string(c.from).size(), c.to);
    const std::string path = dir.write("scene" + std::to_string(++n) + ".json", text);
    const std::string expected = c.error[0] == ':' ? std::string(c.error) : ": " + std::string(c.error);
    checkOneLineError(path, [&] { pbr::loadSceneFile(path); }, expected);
  }
}

TEST_CASE("scene file errors: a missing file, a directory, a non-object document, an empty file") {
  const TempDir dir;
  const std::string missing = dir.file("missing.json");
  checkOneLineError(missing, [&] { pbr::loadSceneFile(missing); }, missing + ": cannot open: No such file or directory");
  checkOneLineError(dir.path().string(), [&] { pbr::loadSceneFile(dir.path().string()); },
                    ": not a regular file (a directory)");
  const std::string array = dir.write("array.json", "[1, 2]");
  checkOneLineError(array, [&] { pbr::loadSceneFile(array); }, ": top level: expected a JSON object, got [1,2]");
  const std::string empty = dir.write("empty.json", "");
  checkOneLineError(empty, [&] { pbr::loadSceneFile(empty); }, ":1:1: JSON syntax error: ");
  const std::string model = dir.file("missing.glb");
  checkOneLineError(model, [&] { pbr::loadSceneFile(model); }, ": cannot open: No such file or directory");
}
