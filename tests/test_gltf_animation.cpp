// glTF animations, skins and morph targets posed at load (GltfSelection, --animation and --time): a two-bone bar bends
// as the joint matrices the test computes say, morph targets move vertices by their weighted displacements, and the
// samplers interpolate as the specification's formulas do (step, linear, spherical linear, cubic spline).
#include <doctest/doctest.h>

#include <cmath>
#include <algorithm>
#include <cstdint>
#include <functional>
#include <tuple>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "core/scene/gltf_loader.hpp"
#include "core/scene/scene_json.hpp"
#include "tests/cli_util.hpp"
#include "tests/gltf_builder.hpp"

using nlohmann::json;
using pbr::test::GltfBuilder;
using pbr::test::TempDir;

namespace {

std::string errorOf(const std::function<void()>& load) {
  try {
    load();
  } catch (const pbr::SceneError& e) {
    return e.what();
  }
  return "";
}

pbr::Scene load(const std::string& path, const pbr::GltfSelection& pose) {
  pbr::Scene scene;
  pbr::appendGltf(scene, path, glm::mat4(1.0f), {}, pose);
  return scene;
}

pbr::GltfSelection at(double time, const std::string& animation = "") {
  pbr::GltfSelection pose;
  pose.time = time;
  if (!animation.empty()) pose.animation = animation;
  return pose;
}

// An animation of one channel: `node`'s `path` through keyframes `times` and `values` (3 or 4 numbers a keyframe,
// three times as many for CUBICSPLINE).
void animate(GltfBuilder& b, int node, const std::string& path, const std::string& interpolation,
             const std::vector<float>& times, const std::vector<float>& values, const char* type,
             const std::string& name = "move") {
  const int input = b.addView(times.data(), times.size() * sizeof(float));
  b.doc["accessors"].push_back({{"bufferView", input}, {"componentType", 5126}, {"count", times.size()},
                                {"type", "SCALAR"}, {"min", {times.front()}}, {"max", {times.back()}}});
  const size_t width = std::string(type) == "VEC4" ? 4 : std::string(type) == "VEC3" ? 3 : 1;
  const int output = b.addView(values.data(), values.size() * sizeof(float));
  b.doc["accessors"].push_back(
      {{"bufferView", output}, {"componentType", 5126}, {"count", values.size() / width}, {"type", type}});
  const int n = static_cast<int>(b.doc["accessors"].size());
  b.doc["animations"].push_back(
      {{"name", name},
       {"samplers", {{{"input", n - 2}, {"output", n - 1}, {"interpolation", interpolation}}}},
       {"channels", {{{"sampler", 0}, {"target", {{"node", node}, {"path", path}}}}}}});
}

void checkNear(const glm::vec3& got, const glm::vec3& expected, float tolerance = 1e-5f) {
  CAPTURE(got.x);
  CAPTURE(got.y);
  CAPTURE(got.z);
  CHECK(glm::length(got - expected) < tolerance);
}

}  // namespace

TEST_CASE("gltf skins: a two-bone bar bent 60 degrees at t = 1 follows the joint matrices the test computes") {
  const TempDir dir;
  GltfBuilder b;
  // The bar: x from 0 to 2 at y = +-0.1, bound half to each joint at x = 1.
  const std::vector<float> xs = {0.0f, 1.0f, 2.0f};
  std::vector<float> positions, normals, weights;
  std::vector<uint8_t> joints;
  for (const float x : xs) {
    for (const float y : {-0.1f, 0.1f}) {
      positions.insert(positions.end(), {x, y, 0.0f});
      normals.insert(normals.end(), {0.0f, 0.0f, 1.0f});
      const float w1 = x / 2.0f;  // 0, 0.5, 1
      weights.insert(weights.end(), {1.0f - w1, w1, 0.0f, 0.0f});
      joints.insert(joints.end(), {0, 1, 0, 0});
    }
  }
  const int jointView = b.addView(joints.data(), joints.size());
  b.doc["accessors"].push_back({{"bufferView", jointView}, {"componentType", 5121}, {"count", 6}, {"type", "VEC4"}});
  const int jointAccessor = static_cast<int>(b.doc["accessors"].size()) - 1;
  const int mesh = b.addMesh({{"attributes",
                               {{"POSITION", b.addFloats(positions, "VEC3")},
                                {"NORMAL", b.addFloats(normals, "VEC3")},
                                {"JOINTS_0", jointAccessor},
                                {"WEIGHTS_0", b.addFloats(weights, "VEC4")}}},
                              {"indices", b.addIndices({0, 2, 3, 0, 3, 1, 2, 4, 5, 2, 5, 3})}});
  // Node 0: the skinned mesh, its own transform to be ignored; node 1: the root joint; node 2: the bending joint.
  const std::vector<float> inverseBind = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1,
                                          1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, -1, 0, 0, 1};
  const int ibmView = b.addView(inverseBind.data(), inverseBind.size() * sizeof(float));
  b.doc["accessors"].push_back({{"bufferView", ibmView}, {"componentType", 5126}, {"count", 2}, {"type", "MAT4"}});
  b.doc["skins"] = {{{"joints", {1, 2}}, {"inverseBindMatrices", b.doc["accessors"].size() - 1}}};
  b.addRootNode({{"mesh", mesh}, {"skin", 0}, {"translation", {5.0, 0.0, 0.0}}});
  b.addRootNode({{"children", {2}}, {"translation", {0.0, 0.0, 0.0}}});
  b.doc["nodes"].push_back({{"translation", {1.0, 0.0, 0.0}}});
  const float s = std::sin(glm::radians(30.0f)), c = std::cos(glm::radians(30.0f));  // half of 60 degrees
  animate(b, 2, "rotation", "LINEAR", {0.0f, 1.0f}, {0, 0, 0, 1, 0, 0, s, c}, "VEC4", "bend");
  const std::string path = b.writeGltf(dir.path(), "bar");

  // The joint matrices at t = 1: the bending joint's world transform times its inverse bind matrix.
  const glm::mat4 bend = glm::translate(glm::mat4(1.0f), {1.0f, 0.0f, 0.0f}) *
                         glm::rotate(glm::mat4(1.0f), glm::radians(60.0f), {0.0f, 0.0f, 1.0f}) *
                         glm::translate(glm::mat4(1.0f), {-1.0f, 0.0f, 0.0f});
  for (const bool posed : {false, true}) {
    CAPTURE(posed);
    const pbr::Scene scene = load(path, posed ? at(1.0, "bend") : pbr::GltfSelection{});
    REQUIRE(scene.objects.size() == 1);
    CHECK(scene.objects[0].transform == glm::mat4(1.0f));  // placed by its joints, not its node
    const std::vector<pbr::Vertex>& v = scene.meshes[static_cast<size_t>(scene.objects[0].mesh)].vertices;
    REQUIRE(v.size() == 6);
    for (size_t i = 0; i < 6; ++i) {
      CAPTURE(i);
      const glm::vec4 p(positions[3 * i], positions[3 * i + 1], 0.0f, 1.0f);
      const float w1 = weights[4 * i + 1];
      const glm::mat4 m = posed ? (1.0f - w1) * glm::mat4(1.0f) + w1 * bend : glm::mat4(1.0f);
      checkNear(v[i].position, glm::vec3(m * p));
      checkNear(v[i].normal, glm::vec3(0.0f, 0.0f, 1.0f));
    }
  }
  // The bar's tip at t = 1 is where the test's rotation puts it: (1 + cos 60, sin 60) on the axis.
  const pbr::Scene bent = load(path, at(1.0));
  const glm::vec3 tip = 0.5f * (bent.meshes[0].vertices[4].position + bent.meshes[0].vertices[5].position);
  checkNear(tip, {1.5f, std::sqrt(3.0f) / 2.0f, 0.0f});
}

TEST_CASE("gltf morph targets: weight 1 moves the vertices by the displacements, the node's weights first") {
  const TempDir dir;
  GltfBuilder b = pbr::test::quadModel();
  json& primitive = b.doc["meshes"][0]["primitives"][0];
  const std::vector<float> up = {0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0.5f};  // vertex 0 by 1, vertex 3 by 0.5
  primitive["targets"] = {{{"POSITION", b.addFloats(up, "VEC3")}}};
  const pbr::Scene still = load(b.writeGltf(dir.path(), "still"), {});
  const std::vector<pbr::Vertex> base = still.meshes[0].vertices;
  for (const auto& [meshWeight, nodeWeight, expected] :
       {std::make_tuple(1.0, -1.0, 1.0f), std::make_tuple(1.0, 0.25, 0.25f), std::make_tuple(0.0, -1.0, 0.0f)}) {
    GltfBuilder m = b;
    m.doc["meshes"][0]["weights"] = {meshWeight};
    if (nodeWeight >= 0.0) m.doc["nodes"][0]["weights"] = {nodeWeight};
    const pbr::Scene s = load(m.writeGltf(dir.path(), "weighted"), {});
    CAPTURE(expected);
    const std::vector<pbr::Vertex>& v = s.meshes[static_cast<size_t>(s.objects[0].mesh)].vertices;
    REQUIRE(v.size() == 4);
    for (size_t i = 0; i < 4; ++i) {
      checkNear(v[i].position, base[i].position + expected * glm::vec3(up[3 * i], up[3 * i + 1], up[3 * i + 2]));
    }
  }
  // An animated weight: linear from 0 to 1 over a second, 0.25 at t = 0.25.
  animate(b, 0, "weights", "LINEAR", {0.0f, 1.0f}, {0.0f, 1.0f}, "SCALAR");
  const pbr::Scene s = load(b.writeGltf(dir.path(), "animated"), at(0.25));
  checkNear(s.meshes[static_cast<size_t>(s.objects[0].mesh)].vertices[0].position,
            base[0].position + glm::vec3(0.0f, 0.0f, 0.25f));
}

TEST_CASE("gltf animation: step, linear, spherical and cubic-spline samplers match the specification's formulas") {
  const TempDir dir;
  const auto translationAt = [&](const std::string& interpolation, const std::vector<float>& times,
                                 const std::vector<float>& values, double t) {
    GltfBuilder b = pbr::test::quadModel();
    animate(b, 0, "translation", interpolation, times, values, "VEC3");
    const pbr::Scene s = load(b.writeGltf(dir.path(), "moved"), at(t));
    return glm::vec3(s.objects[0].transform[3]);
  };
  const std::vector<float> times = {0.0f, 1.0f, 3.0f};
  const std::vector<float> points = {0, 0, 0, 2, 0, 0, 2, 4, 0};
  checkNear(translationAt("STEP", times, points, 0.99), {0, 0, 0});
  checkNear(translationAt("STEP", times, points, 1.5), {2, 0, 0});
  checkNear(translationAt("LINEAR", times, points, 0.25), {0.5f, 0, 0});
  checkNear(translationAt("LINEAR", times, points, 2.0), {2, 2, 0});
  checkNear(translationAt("LINEAR", times, points, -1.0), {0, 0, 0});  // the ends hold
  checkNear(translationAt("LINEAR", times, points, 9.0), {2, 4, 0});
  // CUBICSPLINE: in-tangent a, value v, out-tangent b per keyframe; the formula evaluated here from the values.
  const std::vector<glm::vec3> a = {{0, 0, 0}, {1, -1, 0}, {0, 2, 0}}, v = {{0, 0, 0}, {2, 0, 0}, {2, 4, 0}},
                               bOut = {{3, 1, 0}, {0.5f, 2, 1}, {0, 0, 0}};
  std::vector<float> cubic;
  for (size_t k = 0; k < 3; ++k) {
    for (const glm::vec3& x : {a[k], v[k], bOut[k]}) cubic.insert(cubic.end(), {x.x, x.y, x.z});
  }
  for (const double t : {0.25, 1.5, 2.9}) {
    CAPTURE(t);
    const size_t k = t < 1.0 ? 0 : 1;
    const float td = times[k + 1] - times[k], u = float((t - times[k]) / td);
    const float u2 = u * u, u3 = u2 * u;
    const glm::vec3 expected = (2 * u3 - 3 * u2 + 1) * v[k] + (u3 - 2 * u2 + u) * td * bOut[k] +
                               (-2 * u3 + 3 * u2) * v[k + 1] + (u3 - u2) * td * a[k + 1];
    checkNear(translationAt("CUBICSPLINE", times, cubic, t), expected, 1e-4f);
  }
  // Rotations interpolate spherically: halfway from 0 to 90 degrees about +Y is 45.
  GltfBuilder b = pbr::test::quadModel();
  const float h = std::sqrt(0.5f);
  animate(b, 0, "rotation", "LINEAR", {0.0f, 2.0f}, {0, 0, 0, 1, 0, h, 0, h}, "VEC4");
  const pbr::Scene s = load(b.writeGltf(dir.path(), "turned"), at(1.0));
  checkNear(glm::vec3(s.objects[0].transform * glm::vec4(1, 0, 0, 0)),
            {std::cos(glm::radians(45.0f)), 0.0f, -std::sin(glm::radians(45.0f))});
}

TEST_CASE("gltf animation: chosen by name or index, refused by name when absent, at rest with a note by default") {
  const TempDir dir;
  GltfBuilder b = pbr::test::quadModel();
  animate(b, 0, "translation", "LINEAR", {0.0f, 1.0f}, {0, 0, 0, 4, 0, 0}, "VEC3", "slide");
  const std::string path = b.writeGltf(dir.path(), "slide");
  CHECK(load(path, at(0.5, "slide")).objects[0].transform[3].x == doctest::Approx(2.0f));
  CHECK(load(path, at(0.5, "0")).objects[0].transform[3].x == doctest::Approx(2.0f));
  pbr::GltfSelection named;
  named.animation = "slide";  // time 0 without --time
  CHECK(load(path, named).objects[0].transform[3].x == doctest::Approx(0.0f));
  CHECK(errorOf([&] { load(path, at(0.5, "walk")); }) ==
        path + ": --animation walk: no animation of that name or index (the file has 1: 'slide')");
  const pbr::Scene rest = pbr::loadSceneFile(path);
  CHECK(rest.objects[0].transform[3].x == 0.0f);
  CHECK(std::find(rest.notes.begin(), rest.notes.end(),
                  "slide.gltf has 1 animation: drawn at rest (--animation NAME|INDEX and --time SECONDS pose it)") !=
        rest.notes.end());
  // A file without animations refuses --time by name.
  const std::string still = pbr::test::quadModel().writeGltf(dir.path(), "still");
  CHECK(errorOf([&] { load(still, at(1.0)); }) == still + ": --time: the file has no animations");
}

TEST_CASE("gltf playback: a playable load poses again at any time as a load at that time, hidden nodes kept") {
  const TempDir dir;
  // A quad sliding 4 m along x over 2 s, scaled to nothing from 1 s to 2 s (STEP), carrying a point light 1 m above.
  GltfBuilder b = pbr::test::quadModel();
  animate(b, 0, "translation", "LINEAR", {0.0f, 2.0f}, {0, 0, 0, 4, 0, 0}, "VEC3", "slide");
  const std::vector<float> scaleTimes = {0.0f, 1.0f, 2.0f}, scales = {1, 1, 1, 0, 0, 0, 1, 1, 1};
  const int input = b.addView(scaleTimes.data(), scaleTimes.size() * sizeof(float));
  b.doc["accessors"].push_back({{"bufferView", input}, {"componentType", 5126}, {"count", 3}, {"type", "SCALAR"},
                                {"min", {0.0}}, {"max", {2.0}}});
  const int output = b.addView(scales.data(), scales.size() * sizeof(float));
  b.doc["accessors"].push_back({{"bufferView", output}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}});
  const int n = static_cast<int>(b.doc["accessors"].size());
  b.doc["animations"][0]["samplers"].push_back({{"input", n - 2}, {"output", n - 1}, {"interpolation", "STEP"}});
  b.doc["animations"][0]["channels"].push_back({{"sampler", 1}, {"target", {{"node", 0}, {"path", "scale"}}}});
  b.doc["extensionsUsed"] = {"KHR_lights_punctual"};
  b.doc["extensions"]["KHR_lights_punctual"]["lights"] = {{{"type", "point"}, {"intensity", 10.0}, {"range", 5.0}}};
  b.doc["nodes"][0]["children"] = {1};
  b.doc["nodes"].push_back({{"translation", {0, 1, 0}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
  const std::string path = b.writeGltf(dir.path(), "slide");
  const auto playable = [](double time) {
    pbr::GltfSelection s = at(time, "slide");
    s.playable = true;
    return s;
  };
  const auto checkPosedAs = [&](const pbr::Scene& posed, double time) {
    const pbr::Scene loaded = load(path, at(time, "slide"));
    REQUIRE(loaded.objects.size() == 1);
    CHECK(posed.objects[0].transform == loaded.objects[0].transform);
    CHECK(posed.lights[0].position == loaded.lights[0].position);
    CHECK(posed.lights[0].radius == loaded.lights[0].radius);
    CHECK(posed.lights[0].luminousPower == loaded.lights[0].luminousPower);
  };
  const auto checkHidden = [](const pbr::Scene& posed) {
    CHECK(posed.objects[0].transform == glm::mat4(0.0f));
    CHECK(posed.lights[0].radius == 0.0f);
    CHECK(posed.lights[0].luminousPower == 0.0f);
  };
  // A load at 1.5 s leaves the hidden quad and its light out; a playable one keeps both, as nothing.
  CHECK(load(path, at(1.5, "slide")).objects.empty());
  for (const double start : {0.0, 1.5}) {
    CAPTURE(start);
    pbr::Scene scene = load(path, playable(start));
    REQUIRE(scene.gltfPlayback.size() == 1);
    CHECK(scene.gltfPlayback[0]->duration == 2.0);
    CHECK(scene.gltfPlayback[0]->animationName == "slide");
    REQUIRE(scene.objects.size() == 1);
    REQUIRE(scene.lights.size() == 1);
    if (start > 1.0) checkHidden(scene);
    CHECK(pbr::posePlayback(scene, 0.5).empty());  // nothing deformed: no mesh rewritten
    checkPosedAs(scene, 0.5);
    CHECK(scene.objects[0].transform[3].x == doctest::Approx(1.0f));
    CHECK(scene.lights[0].position == glm::vec3(1.0f, 1.0f, 0.0f));
    pbr::posePlayback(scene, 1.5);
    checkHidden(scene);
    pbr::posePlayback(scene, 2.5);
    checkPosedAs(scene, 2.5);
  }
}
