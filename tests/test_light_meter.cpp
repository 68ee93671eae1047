// The exposure a glTF model given alone gets from its own lights: the incident-light meter's reading at the model,
// evaluated here from the light list and the formulas (inverse square, the distance window, glTF's cone, ISO 2720's
// calibration), and the cases where no meter is used.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "core/scene/exposure.hpp"
#include "core/scene/scene_json.hpp"
#include "tests/cli_util.hpp"
#include "tests/gltf_builder.hpp"

using nlohmann::json;
using pbr::test::GltfBuilder;
using pbr::test::TempDir;

namespace {

constexpr double kPi = 3.14159265358979323846;

json lightNode(int light, const json& translation) {
  return {{"translation", translation}, {"extensions", {{"KHR_lights_punctual", {{"light", light}}}}}};
}

// The default 2 x 2 quad (bounds centre the origin, bounding radius sqrt 2) with `lights` on nodes of their own.
std::string quadWithLights(const TempDir& dir, const json& lights, const json& lightNodes) {
  GltfBuilder b = pbr::test::quadModel();
  b.doc["extensionsUsed"] = {"KHR_lights_punctual"};
  b.doc["extensions"]["KHR_lights_punctual"]["lights"] = lights;
  for (const json& node : lightNodes) b.addRootNode(node);
  return b.writeGltf(dir.path(), "lit");
}

double window(double d, double range) { return std::pow(std::clamp(1.0 - std::pow(d / range, 4.0), 0.0, 1.0), 2.0); }

bool hasNote(const pbr::Scene& scene, const std::string& text) {
  return std::any_of(scene.notes.begin(), scene.notes.end(),
                     [&](const std::string& n) { return n.find(text) != std::string::npos; });
}

}  // namespace

TEST_CASE("light meter: a model with lights in physical units gets the EV100 an incident-light meter reads at it") {
  const TempDir dir;
  const double radius = std::sqrt(2.0);  // the quad's bounding sphere
  // A point light 4 above the centre; a bright spot 3 above it shining away (rotated 180 degrees about X, so its
  // -Z points up); a green light inside the bounding sphere, counted at its surface; a tinted sun.
  const json lights = {{{"type", "point"}, {"intensity", 100.0}, {"range", 50.0}},
                       {{"type", "spot"}, {"intensity", 1e6}, {"spot", {{"outerConeAngle", 0.5}}}},
                       {{"type", "point"}, {"intensity", 20.0}, {"color", {0.0, 1.0, 0.0}}},
                       {{"type", "directional"}, {"intensity", 1000.0}, {"color", {1.0, 0.5, 0.25}}}};
  json spot = lightNode(1, {0, 0, 3});
  spot["rotation"] = {1, 0, 0, 0};
  const std::string path = quadWithLights(dir, lights, {lightNode(0, {0, 0, 4}), spot, lightNode(2, {0.5, 0, 0.2}),
                                                        {{"extensions", {{"KHR_lights_punctual", {{"light", 3}}}}}}});
  const pbr::Scene scene = pbr::loadSceneFile(path);

  // Rec. 709 luminance of each colour; the spot adds nothing; the near light's window is 1 at the sphere.
  const double lux = 100.0 / 16.0 * window(4.0 - radius, 50.0) + 20.0 * 0.7152 / (radius * radius) +
                     1000.0 * (0.2126 + 0.7152 * 0.5 + 0.0722 * 0.25);
  const double ev = std::log2(lux * 100.0 / 250.0);
  MESSAGE("illuminance " << lux << " lux, EV100 " << ev);
  REQUIRE(scene.ev100.has_value());
  CHECK(*scene.ev100 == doctest::Approx(ev).epsilon(1e-5));
  // What the loader invented follows: the ambient light as at exposure 1, the sky two stops below.
  const double level = 1.2 * std::exp2(ev);
  CHECK(scene.ambient.x == doctest::Approx(0.03 * level).epsilon(1e-5));
  REQUIRE(scene.environment.has_value());
  CHECK(scene.environment->intensity == doctest::Approx(0.25 * level).epsilon(1e-5));
  char evText[32];
  std::snprintf(evText, sizeof evText, "EV100 %.2f", ev);
  CHECK(hasNote(scene, evText));
  // A white Lambert surface under the meter's illuminance shows E / pi at 250 / (120 pi) = 0.66 of white.
  CHECK(lux / kPi * pbr::exposureFromEv100(*scene.ev100) == doctest::Approx(250.0 / (120.0 * kPi)).epsilon(1e-4));
}

TEST_CASE("light meter: no meter without lights to read, and none for a scene file, which states its exposure") {
  const TempDir dir;
  // Silent about lights: the default rig at exposure 1.
  GltfBuilder plain = pbr::test::quadModel();
  const std::string plainPath = plain.writeGltf(dir.path(), "plain");
  const pbr::Scene rig = pbr::loadSceneFile(plainPath);
  CHECK_FALSE(rig.lights.empty());
  CHECK_FALSE(rig.ev100.has_value());
  CHECK(rig.displayExposure() == 1.0f);
  // Black lights give nothing to meter.
  const pbr::Scene black = pbr::loadSceneFile(
      quadWithLights(dir, {{{"type", "point"}, {"intensity", 0.0}}}, json::array({lightNode(0, {0, 0, 2})})));
  CHECK_FALSE(black.ev100.has_value());
  CHECK(black.ambient.x == doctest::Approx(0.03));
  CHECK_FALSE(hasNote(black, "EV100"));
  // A JSON scene placing the lit model keeps its own camera's exposure (here none).
  const std::string lit =
      quadWithLights(dir, {{{"type", "point"}, {"intensity", 1000.0}}}, json::array({lightNode(0, {0, 0, 2})}));
  const pbr::Scene placed = pbr::loadSceneFile(
      dir.write("placed.json", R"({"camera": {"position": [0, 0, 5], "target": [0, 0, 0]}, "objects": [{"gltf": ")" +
                                   lit + R"("}]})"));
  CHECK_FALSE(placed.ev100.has_value());
  CHECK(placed.displayExposure() == 1.0f);
}
