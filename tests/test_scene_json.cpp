// Scene files: what a valid JSON file turns into, the transform order, light counts, textures and glTF objects.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "core/io/image_output.hpp"
#include "core/scene/assets.hpp"
#include "core/scene/builtin_scenes.hpp"
#include "core/scene/gltf_loader.hpp"
#include "core/scene/model_scene.hpp"
#include "core/scene/scene_json.hpp"
#include "tests/cli_util.hpp"
#include "tests/gltf_builder.hpp"

namespace fs = std::filesystem;
using pbr::test::TempDir;

namespace {

// A function, not a global: a missing asset must fail the cases that use it, not the whole test binary.
std::string boxAsset() { return pbr::assetPath("BoxTextured/glTF-Embedded/BoxTextured.gltf"); }

void checkVec(const glm::vec3& got, const glm::vec3& want, float eps = 1e-6f) {
  for (int i = 0; i < 3; ++i) CHECK(got[i] == doctest::Approx(want[i]).epsilon(eps));
}

}  // namespace

TEST_CASE("scene file: every field of a valid file reaches the scene") {
  const TempDir dir;
  const std::string path = dir.write("round.json", R"({
    "camera": {"position": [1, 2, 3], "target": [0, 0.5, 0], "up": [0, 0, 1], "fov_y_deg": 35, "near": 0.25, "far": 50},
    "exposure": 2.5,
    "ambient": [0.1, 0.2, 0.3],
    "objects": [
      {"shape": "plane", "transform": {"scale": 10}},
      {"shape": "box", "transform": {"translate": [1, 0.5, -2], "scale": [1, 2, 3]},
       "material": {"base_color": 0.25, "double_sided": true, "alpha": 0.25, "alpha_mode": "blend"}},
      {"shape": "sphere", "material": {"base_color": [0.9, 0.1, 0.2], "roughness": 0.3, "metalness": 1,
                                       "emissive": [2, 1, 0], "alpha_mode": "mask", "alpha_cutoff": 0.75}}
    ],
    "lights": [
      {"position": [0, 3, 0], "color": [1, 0.5, 0.25], "luminous_power": 800, "radius": 6},
      {"position": [2, 1, 0], "intensity_cd": 10, "radius": 0}
    ],
    "random_lights": {"count": 5, "seed": 3, "bounds": [[-1, 0, -2], [1, 2, 2]], "radius": [0.5, 1], "luminous_power": [10, 30]}
  })");
  const pbr::Scene s = pbr::loadSceneFile(path);
  CHECK(s.name == "round");
  checkVec(s.camera.position, {1, 2, 3});
  checkVec(s.camera.target, {0, 0.5f, 0});
  checkVec(s.camera.up, {0, 0, 1});
  CHECK(s.camera.fovYDeg == 35.0f);
  CHECK(s.camera.nearPlane == 0.25f);
  CHECK(s.camera.farPlane == 50.0f);
  CHECK(s.exposure == 2.5f);
  checkVec(s.ambient, {0.1f, 0.2f, 0.3f});

  REQUIRE(s.objects.size() == 3);
  CHECK(s.meshes.size() == 3);
  CHECK(s.objects[0].shape == pbr::Shape::Plane);
  CHECK(s.objects[0].transform == glm::scale(glm::mat4(1.0f), glm::vec3(10.0f)));
  const pbr::Material defaults;
  CHECK(s.objects[0].material.baseColor == defaults.baseColor);
  CHECK(s.objects[0].material.roughness == defaults.roughness);
  CHECK_FALSE(s.objects[0].material.doubleSided);
  CHECK(s.objects[0].material.alpha == defaults.alpha);
  CHECK(s.objects[0].material.alphaMode == pbr::AlphaMode::Opaque);
  CHECK(s.objects[0].material.alphaCutoff == defaults.alphaCutoff);
  CHECK(s.objects[1].shape == pbr::Shape::Box);
  CHECK(s.objects[1].transform == glm::scale(glm::translate(glm::mat4(1.0f), {1, 0.5f, -2}), {1, 2, 3}));
  checkVec(s.objects[1].material.baseColor, glm::vec3(0.25f));
  CHECK(s.objects[1].material.doubleSided);
  CHECK(s.objects[1].material.alpha == 0.25f);
  CHECK(s.objects[1].material.alphaMode == pbr::AlphaMode::Blend);
  CHECK(s.objects[2].shape == pbr::Shape::Sphere);
  CHECK(s.objects[2].transform == glm::mat4(1.0f));
  checkVec(s.objects[2].material.baseColor, {0.9f, 0.1f, 0.2f});
  CHECK(s.objects[2].material.roughness == 0.3f);
  CHECK(s.objects[2].material.metalness == 1.0f);
  checkVec(s.objects[2].material.emissive, {2, 1, 0});
  CHECK(s.objects[2].material.baseColorTexture == -1);
  CHECK(s.objects[2].material.alphaMode == pbr::AlphaMode::Mask);
  CHECK(s.objects[2].material.alphaCutoff == 0.75f);
  CHECK(s.objects[2].material.alpha == defaults.alpha);

  REQUIRE(s.lights.size() == 2 + 5);
  checkVec(s.lights[0].position, {0, 3, 0});
  checkVec(s.lights[0].color, {1, 0.5f, 0.25f});
  CHECK(s.lights[0].luminousPower == 800.0f);
  CHECK(s.lights[0].radius == 6.0f);
  checkVec(s.lights[1].color, glm::vec3(1.0f));  // white unless given
  CHECK(s.lights[1].luminousPower == doctest::Approx(4.0 * glm::pi<double>() * 10.0));
  CHECK(s.lights[1].radius == 0.0f);
  pbr::RandomLightSpec spec;
  spec.count = 5;
  spec.seed = 3;
  spec.boundsMin = {-1, 0, -2};
  spec.boundsMax = {1, 2, 2};
  spec.radiusMin = 0.5f;
  spec.radiusMax = 1.0f;
  spec.powerMin = 10.0f;
  spec.powerMax = 30.0f;
  const std::vector<pbr::PointLight> random = pbr::makeRandomLights(spec);
  for (size_t i = 0; i < random.size(); ++i) {
    CAPTURE(i);
    CHECK(s.lights[2 + i].position == random[i].position);
    CHECK(s.lights[2 + i].color == random[i].color);
    CHECK(s.lights[2 + i].radius == random[i].radius);
    CHECK(s.lights[2 + i].luminousPower == random[i].luminousPower);
  }
}

TEST_CASE("scene file: directional lights and the camera's exposure value") {
  const TempDir dir;
  const std::string path = dir.write("sun.json", R"({
    "camera": {"position": [0, 2, 6], "target": [0, 0, 0], "ev100": 15},
    "exposure": 2,
    "lights": [
      {"type": "directional", "direction": [0, -2, 0], "illuminance_lux": 100000, "color": [1, 0.9, 0.8]},
      {"position": [0, 3, 0], "luminous_power": 800, "radius": 6}
    ]
  })");
  const pbr::Scene s = pbr::loadSceneFile(path);
  REQUIRE(s.directionalLights.size() == 1);
  REQUIRE(s.lights.size() == 1);
  checkVec(s.directionalLights[0].direction, {0, -1, 0});  // normalised
  CHECK(s.directionalLights[0].illuminance == 100000.0f);
  checkVec(s.directionalLights[0].color, {1, 0.9f, 0.8f});
  REQUIRE(s.ev100.has_value());
  CHECK(*s.ev100 == 15.0f);
  // Lmax = 1.2 * 2^EV100 maps to 1, then the plain multiplier.
  CHECK(s.displayExposure() == doctest::Approx(2.0 / (1.2 * 32768.0)).epsilon(1e-6));

  // f/16 at 1/125 s and ISO 200: EV100 = log2(16^2 * 125 * 100 / 200) = log2(16000).
  const std::string settings = dir.write("settings.json", R"({
    "camera": {"position": [0, 2, 6], "target": [0, 0, 0], "aperture": 16, "shutter_s": 0.008, "iso": 200}
  })");
  const pbr::Scene t = pbr::loadSceneFile(settings);
  REQUIRE(t.ev100.has_value());
  CHECK(*t.ev100 == doctest::Approx(std::log2(16000.0)).epsilon(1e-6));
  // Without an exposure value the plain multiplier is all there is.
  const std::string plain = dir.write("plain.json", R"({"camera": {"position": [0, 2, 6], "target": [0, 0, 0]}, "exposure": 3})");
  CHECK_FALSE(pbr::loadSceneFile(plain).ev100.has_value());
  CHECK(pbr::loadSceneFile(plain).displayExposure() == 3.0f);
}

TEST_CASE("scene file: a camera alone is a scene, omitted fields take their documented defaults") {
  const TempDir dir;
  const pbr::Scene s =
      pbr::loadSceneFile(dir.write("min.json", R"({"camera": {"position": [0, 1, 5], "target": [0, 0, 0]}})"));
  const pbr::Camera defaults;
  CHECK(s.camera.up == defaults.up);
  CHECK(s.camera.fovYDeg == defaults.fovYDeg);
  CHECK(s.camera.nearPlane == defaults.nearPlane);
  CHECK(s.camera.farPlane == defaults.farPlane);
  CHECK(s.exposure == 1.0f);
  CHECK(s.ambient == glm::vec3(0.0f));
  CHECK(s.objects.empty());
  CHECK(s.lights.empty());
}

TEST_CASE("scene file: scale, then rotate_deg about X, then Y, then Z, then translate") {
  const TempDir dir;
  const pbr::Scene s = pbr::loadSceneFile(dir.write("t.json", R"({
    "camera": {"position": [0, 1, 5], "target": [0, 0, 0]},
    "objects": [{"shape": "box", "transform": {"translate": [1, -2, 3], "rotate_deg": [30, 45, 60], "scale": [2, 3, 4]}}]
  })"));
  REQUIRE(s.objects.size() == 1);
  // Built by hand, column by column, so that the test shares no code with the loader.
  const float a = glm::radians(30.0f), b = glm::radians(45.0f), c = glm::radians(60.0f);
  const glm::mat4 rx(1, 0, 0, 0, 0, std::cos(a), std::sin(a), 0, 0, -std::sin(a), std::cos(a), 0, 0, 0, 0, 1);
  const glm::mat4 ry(std::cos(b), 0, -std::sin(b), 0, 0, 1, 0, 0, std::sin(b), 0, std::cos(b), 0, 0, 0, 0, 1);
  const glm::mat4 rz(std::cos(c), std::sin(c), 0, 0, -std::sin(c), std::cos(c), 0, 0, 0, 0, 1, 0, 0, 0, 0, 1);
  const glm::mat4 scale(2, 0, 0, 0, 0, 3, 0, 0, 0, 0, 4, 0, 0, 0, 0, 1);
  const glm::mat4 translate(1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 1, -2, 3, 1);
  const glm::vec4 p(0.5f, -0.25f, 0.125f, 1.0f);
  const glm::vec4 want = translate * (rz * (ry * (rx * (scale * p))));
  const glm::vec4 got = s.objects[0].transform * p;
  checkVec(glm::vec3(got), glm::vec3(want), 1e-5f);
  // The opposite order lands elsewhere, so the check above does tell the orders apart.
  const glm::vec4 other = translate * (rx * (ry * (rz * (scale * p))));
  CHECK(glm::length(glm::vec3(other - want)) > 0.1f);
}

TEST_CASE("scene file: a light count replaces random_lights.count and is refused without random_lights") {
  const TempDir dir;
  const std::string random = dir.write("r.json", R"({
    "camera": {"position": [0, 1, 5], "target": [0, 0, 0]},
    "lights": [{"position": [0, 2, 0], "luminous_power": 100, "radius": 4}],
    "random_lights": {"count": 3, "bounds": [[-1, 0, -1], [1, 1, 1]], "radius": [1, 2], "luminous_power": [1, 2]}
  })");
  CHECK(pbr::loadSceneFile(random).lights.size() == 1 + 3);
  CHECK(pbr::loadSceneFile(random, 40).lights.size() == 1 + 40);
  CHECK(pbr::loadSceneFile(random, 0).lights.size() == 1);
  const std::string fixed = dir.write("f.json", R"({
    "camera": {"position": [0, 1, 5], "target": [0, 0, 0]},
    "lights": [{"position": [0, 2, 0], "luminous_power": 100, "radius": 4}]
  })");
  CHECK(pbr::loadSceneFile(fixed).lights.size() == 1);
  CHECK_THROWS_WITH_AS(pbr::loadSceneFile(fixed, 8), doctest::Contains("random_lights"), pbr::SceneError);
}

TEST_CASE("scene file: spot lights, and a spot share of random lights that leaves the lights where they were") {
  const TempDir dir;
  const std::string path = dir.write("spots.json", R"({
    "camera": {"position": [0, 1, 5], "target": [0, 0, 0]},
    "lights": [{"type": "spot", "position": [0, 2, 0], "direction": [0, -2, 0], "intensity_cd": 10, "radius": 4,
                "inner_angle_deg": 10, "outer_angle_deg": 30},
               {"type": "spot", "position": [1, 2, 0], "direction": [1, 0, 0], "luminous_power": 100, "radius": 4}],
    "random_lights": {"count": 400, "bounds": [[-1, 0, -1], [1, 1, 1]], "radius": [1, 2], "luminous_power": [1, 2],
                      "spot_share": 0.25}
  })");
  const pbr::Scene s = pbr::loadSceneFile(path);
  REQUIRE(s.lights.size() == 2 + 400);
  REQUIRE(s.lights[0].spot.has_value());
  checkVec(s.lights[0].spot->direction, {0, -1, 0});
  CHECK(s.lights[0].spot->innerAngle == doctest::Approx(glm::radians(10.0)));
  CHECK(s.lights[0].spot->outerAngle == doctest::Approx(glm::radians(30.0)));
  CHECK(s.lights[0].luminousPower == doctest::Approx(4.0 * glm::pi<double>() * 10.0));
  // glTF's defaults: inner 0, outer 45 degrees.
  CHECK(s.lights[1].spot->innerAngle == 0.0f);
  CHECK(s.lights[1].spot->outerAngle == doctest::Approx(glm::radians(45.0)));
  const auto spots = [](const pbr::Scene& scene) {
    return std::count_if(scene.lights.begin() + 2, scene.lights.end(), [](const pbr::PointLight& l) {
      return l.spot && l.spot->direction.y <= 0.0f && l.spot->innerAngle <= l.spot->outerAngle &&
             l.spot->outerAngle >= glm::radians(10.0f) - 1e-6f && l.spot->outerAngle <= glm::radians(60.0f) + 1e-6f;
    });
  };
  CHECK(spots(s) > 60);
  CHECK(spots(s) < 140);
  // The share given on the command line replaces the file's; positions, radii, colours and powers stay.
  const pbr::Scene none = pbr::loadSceneFile(path, -1, {}, false, pbr::DefaultEnvironment::Sky, 0.0f);
  const pbr::Scene all = pbr::loadSceneFile(path, -1, {}, false, pbr::DefaultEnvironment::Sky, 1.0f);
  CHECK(spots(none) == 0);
  CHECK(spots(all) == 400);
  for (size_t i = 2; i < s.lights.size(); ++i) {
    CHECK(none.lights[i].position == all.lights[i].position);
    CHECK(none.lights[i].radius == s.lights[i].radius);
    CHECK(none.lights[i].luminousPower == all.lights[i].luminousPower);
  }
  const std::string fixed = dir.write("f.json", R"({
    "camera": {"position": [0, 1, 5], "target": [0, 0, 0]},
    "lights": [{"position": [0, 2, 0], "luminous_power": 100, "radius": 4}]
  })");
  CHECK_THROWS_WITH_AS(pbr::loadSceneFile(fixed, -1, {}, false, pbr::DefaultEnvironment::Sky, 0.5f), doctest::Contains("spot-light share"),
                       pbr::SceneError);
}

TEST_CASE("scene file: base_color_texture loads an sRGB image relative to the file, once per path") {
  const TempDir dir;
  pbr::ImageRgba8 image{2, 1, {10, 20, 30, 255, 200, 100, 50, 255}};
  fs::create_directories(dir.path() / "maps");
  pbr::writePng(dir.file("maps/t.png"), image);
  const pbr::Scene s = pbr::loadSceneFile(dir.write("scenes/tex.json", R"({
    "camera": {"position": [0, 1, 5], "target": [0, 0, 0]},
    "objects": [{"shape": "plane", "material": {"base_color_texture": "../maps/t.png"}},
                {"shape": "box", "material": {"base_color_texture": "../maps/t.png"}},
                {"shape": "sphere"}]
  })"));
  REQUIRE(s.textures.size() == 1);
  CHECK(s.textures[0].width == 2);
  CHECK(s.textures[0].height == 1);
  CHECK(s.textures[0].rgba == image.pixels);
  CHECK(s.textures[0].srgb);
  CHECK(s.objects[0].material.baseColorTexture == 0);
  CHECK(s.objects[1].material.baseColorTexture == 0);
  CHECK(s.objects[2].material.baseColorTexture == -1);
}

TEST_CASE("scene file: frameBounds fits the bounding sphere in the vertical field of view") {
  const pbr::Bounds bounds{{-1, -2, -3}, {3, 4, 5}};
  const pbr::Camera c = pbr::frameBounds(bounds, 45.0f);
  const glm::vec3 centre(1, 1, 1);
  const float radius = 0.5f * glm::length(bounds.max - bounds.min);
  checkVec(c.target, centre);
  const glm::vec3 offset = c.position - centre;
  checkVec(glm::normalize(offset), glm::normalize(glm::vec3(0.5f, 0.4f, 1.0f)), 1e-5f);
  const float distance = glm::length(offset);
  CHECK(std::asin(radius / distance) < glm::radians(22.5f));
  CHECK(std::asin(radius / distance) > glm::radians(0.8f * 22.5f));  // framed, not lost in the middle
  CHECK(c.nearPlane > 0.0f);
  CHECK(c.nearPlane < distance - radius);
  CHECK(c.farPlane > distance + radius);
}

TEST_CASE("scene file: the default light rig scales with the model") {
  const pbr::Bounds small{{-1, -1, -1}, {1, 1, 1}}, large{{8, -10, -10}, {28, 10, 10}};
  const std::vector<pbr::PointLight> a = pbr::defaultLightRig(small), b = pbr::defaultLightRig(large);
  REQUIRE(a.size() == b.size());
  REQUIRE(a.size() >= 2);
  for (size_t i = 0; i < a.size(); ++i) {
    CAPTURE(i);
    CHECK(a[i].color == glm::vec3(1.0f));
    checkVec(b[i].position - glm::vec3(18, 0, 0), a[i].position * 10.0f, 1e-5f);
    CHECK(b[i].radius == doctest::Approx(a[i].radius * 10.0f));
    // Ten times farther, a hundred times the power: the same illuminance on the model.
    CHECK(b[i].luminousPower == doctest::Approx(a[i].luminousPower * 100.0f));
    // Every light reaches past the far side of the model.
    CHECK(a[i].radius > glm::length(a[i].position) + std::sqrt(3.0f));
  }
}

TEST_CASE("scene file: glTF objects resolve relative to the scene file and take its transform") {
  const TempDir dir;
  fs::create_directories(dir.path() / "models");
  fs::copy_file(boxAsset(), dir.path() / "models" / "box.gltf");
  const pbr::Scene s = pbr::loadSceneFile(dir.write("scenes/with_model.json", R"({
    "camera": {"position": [0, 1, 5], "target": [0, 0, 0]},
    "objects": [{"shape": "plane", "transform": {"scale": 10}},
                {"gltf": "../models/box.gltf", "transform": {"translate": [0, 2, 0], "scale": 3}}]
  })"));
  pbr::Scene direct;
  pbr::appendGltf(direct, boxAsset());
  REQUIRE(s.objects.size() == 1 + direct.objects.size());
  const glm::mat4 placement = glm::scale(glm::translate(glm::mat4(1.0f), {0, 2, 0}), glm::vec3(3.0f));
  for (size_t i = 0; i < direct.objects.size(); ++i) {
    const glm::mat4 want = placement * direct.objects[i].transform;
    for (int col = 0; col < 4; ++col) checkVec(glm::vec3(s.objects[1 + i].transform[col]), glm::vec3(want[col]), 1e-5f);
  }
  CHECK(s.textures.size() == direct.textures.size());
}

TEST_CASE("scene file: an \"asset:\" path is in the shared asset folder, wherever the scene file is") {
  const TempDir dir;
  const pbr::Scene s = pbr::loadSceneFile(dir.write("asset.json", R"({
    "camera": {"position": [0, 1, 5], "target": [0, 0, 0]},
    "objects": [{"gltf": "asset:BoxTextured/glTF-Embedded/BoxTextured.gltf"}]
  })"));
  pbr::Scene direct;
  pbr::appendGltf(direct, boxAsset());
  CHECK(s.objects.size() == direct.objects.size());
  const std::string missing = dir.write("missing.json", R"({
    "camera": {"position": [0, 1, 5], "target": [0, 0, 0]},
    "objects": [{"gltf": "asset:Nothing/none.gltf"}]
  })");
  const std::string expected =
      missing + ": objects[0].gltf: " + pbr::assetDir() + "/Nothing/none.gltf: asset not found";
  CHECK_THROWS_WITH_AS(pbr::loadSceneFile(missing), doctest::Contains(expected.c_str()), pbr::SceneError);
}

TEST_CASE("scene file: a .gltf given alone is framed and lit by the default rig") {
  pbr::Scene direct;
  const pbr::Bounds bounds = pbr::appendGltf(direct, boxAsset());
  const pbr::Scene s = pbr::loadSceneFile(boxAsset());
  CHECK(s.name == "BoxTextured");
  CHECK(s.objects.size() == direct.objects.size());
  const pbr::Camera framed = pbr::frameBounds(bounds, 45.0f);
  checkVec(s.camera.position, framed.position);
  checkVec(s.camera.target, framed.target);
  CHECK(s.ambient.x > 0.0f);
  CHECK(s.lights.size() == pbr::defaultLightRig(bounds).size());
  // The rig is said, not slipped in (the sky's note is the other one: test_scene_environment.cpp).
  REQUIRE(s.notes.size() == 2);
  CHECK(s.notes[0].find("default rig") != std::string::npos);
  CHECK_THROWS_WITH_AS(pbr::loadSceneFile(boxAsset(), 10), doctest::Contains("light count"), pbr::SceneError);
}

TEST_CASE("scene file: a model that places no light gets the default rig, even when it lists lights") {
  const TempDir dir;
  pbr::test::GltfBuilder builder = pbr::test::quadModel();
  builder.doc["extensionsUsed"] = {"KHR_lights_punctual"};
  builder.doc["extensions"]["KHR_lights_punctual"]["lights"] = nlohmann::json::array();
  for (const int listed : {0, 1}) {
    // An empty light list, then a light no node places.
    if (listed) builder.doc["extensions"]["KHR_lights_punctual"]["lights"] = {{{"type", "point"}}};
    const pbr::Scene declared = pbr::loadSceneFile(builder.writeGltf(dir.path(), "declared"));
    CHECK_FALSE(declared.gltfPlacedLights);
    CHECK(declared.lights.size() == 3);
    REQUIRE_FALSE(declared.notes.empty());
    CHECK(declared.notes[0] == "the file places no lights: lit by a default rig of three point lights");
  }
  // A spot light is loaded as one, along its node's -Z.
  builder.doc["extensions"]["KHR_lights_punctual"]["lights"] = {
      {{"type", "spot"}, {"intensity", 10.0}, {"spot", {{"innerConeAngle", 0.25}, {"outerConeAngle", 0.5}}}}};
  builder.doc["nodes"].push_back({{"rotation", {-0.70710678, 0.0, 0.0, 0.70710678}},
                                  {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
  builder.doc["scenes"][0]["nodes"].push_back(1);
  const pbr::Scene spot = pbr::loadSceneFile(builder.writeGltf(dir.path(), "spot"));
  REQUIRE(spot.lights.size() == 1);
  REQUIRE(spot.lights[0].spot.has_value());
  checkVec(spot.lights[0].spot->direction, glm::vec3(0.0f, -1.0f, 0.0f));
  CHECK(spot.lights[0].spot->innerAngle == doctest::Approx(0.25));
  CHECK(spot.lights[0].spot->outerAngle == doctest::Approx(0.5));
  CHECK(spot.gltfPlacedLights);
  for (const std::string& note : spot.notes) CHECK(note.find("default rig") == std::string::npos);
  // A directional light alone is a light: no rig either.
  builder.doc["extensions"]["KHR_lights_punctual"]["lights"][0] = {{"type", "directional"}, {"intensity", 2.0}};
  const pbr::Scene sun = pbr::loadSceneFile(builder.writeGltf(dir.path(), "sun"));
  CHECK(sun.lights.empty());
  CHECK(sun.directionalLights.size() == 1);
}

TEST_CASE("scene file: the glTF extensions' material fields reach the material, an ior in (0, 1) refused") {
  const TempDir dir;
  const pbr::Scene s = pbr::loadSceneFile(dir.write("specular.json", R"({
    "camera": {"position": [0, 0, 5], "target": [0, 0, 0]},
    "objects": [{"shape": "sphere", "material": {"ior": 1.33, "specular": 0.25, "specular_color": [2, 1, 0.5],
                                                 "clearcoat": 0.5, "clearcoat_roughness": 0.125,
                                                 "sheen_color": [1, 0.5, 0], "sheen_roughness": 0.25}},
                {"shape": "sphere", "material": {"ior": 0, "specular_color": 0.5, "transmission": 0.75,
                                                 "thickness": 0.5, "attenuation_color": [1, 0.5, 0.25],
                                                 "attenuation_distance": 2}},
                {"shape": "sphere"}]
  })"));
  REQUIRE(s.objects.size() == 3);
  CHECK(s.objects[0].material.ior == 1.33f);
  CHECK(s.objects[0].material.specular == 0.25f);
  checkVec(s.objects[0].material.specularColor, {2, 1, 0.5f});
  CHECK(s.objects[0].material.clearcoat == 0.5f);
  CHECK(s.objects[0].material.clearcoatRoughness == 0.125f);
  checkVec(s.objects[0].material.sheenColor, {1, 0.5f, 0});
  CHECK(s.objects[0].material.sheenRoughness == 0.25f);
  CHECK(s.objects[1].material.ior == 0.0f);
  checkVec(s.objects[1].material.specularColor, glm::vec3(0.5f));
  CHECK(s.objects[1].material.transmission == 0.75f);
  CHECK(s.objects[1].material.thickness == 0.5f);
  checkVec(s.objects[1].material.attenuationColor, {1, 0.5f, 0.25f});
  CHECK(s.objects[1].material.attenuationDistance == 2.0f);
  CHECK(s.objects[2].material.ior == 1.5f);
  CHECK(s.objects[2].material.specular == 1.0f);
  CHECK(s.objects[2].material.transmission == 0.0f);
  CHECK(std::isinf(s.objects[2].material.attenuationDistance));  // no absorption
  const std::string bad = dir.write("bad.json", R"({"camera": {"position": [0, 0, 5], "target": [0, 0, 0]},
                                                      "objects": [{"shape": "sphere", "material": {"ior": 0.5}}]})");
  CHECK_THROWS_WITH_AS(pbr::loadSceneFile(bad), doctest::Contains("ior"), pbr::SceneError);
  const std::string none = dir.write("none.json", R"({"camera": {"position": [0, 0, 5], "target": [0, 0, 0]},
    "objects": [{"shape": "sphere", "material": {"attenuation_distance": 0}}]})");
  CHECK_THROWS_WITH_AS(pbr::loadSceneFile(none), doctest::Contains("attenuation_distance"), pbr::SceneError);
}
