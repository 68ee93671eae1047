// Loading glTF 2.0 files into pbr::Scene without a GPU: the shared sample assets, and small files written here
// whose expected contents the tests know from what they wrote.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <draco/compression/encode.h>
#include <draco/mesh/triangle_soup_mesh_builder.h>
#include <glm/geometric.hpp>
#include <meshoptimizer.h>
#include <webp/decode.h>
#include <webp/encode.h>
#include <glm/gtc/matrix_transform.hpp>

#include "core/scene/assets.hpp"
#include "core/scene/builtin_scenes.hpp"
#include "core/scene/gltf_loader.hpp"
#include "core/scene/model_scene.hpp"
#include "core/scene/mesh_tangent_space.hpp"
#include "gbuffer/gbuffer_precision.hpp"
#include "tests/cli_util.hpp"
#include "tests/gltf_builder.hpp"

using nlohmann::json;
using pbr::test::GltfBuilder;
using pbr::test::QuadSpec;
using pbr::test::TempDir;

namespace {

constexpr float kPi = 3.14159265358979f;

size_t triangles(const pbr::Scene& scene) {
  size_t n = 0;
  for (const pbr::SceneObject& o : scene.objects) n += scene.meshes[static_cast<size_t>(o.mesh)].indices.size() / 3;
  return n;
}

// The message of the SceneError `load` throws; fails the test when it throws none.
std::string errorOf(const std::function<void()>& load) {
  try {
    load();
  } catch (const pbr::SceneError& e) {
    return e.what();
  }
  FAIL("expected a pbr::SceneError");
  return {};
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// The angle in degrees between two vectors.
float degreesBetween(const glm::vec3& a, const glm::vec3& b) {
  return glm::degrees(std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0f, 1.0f)));
}

// A one-quad file: its path after writing `builder` with the quad, untextured unless the spec names a material.
std::string quadFile(const TempDir& dir, const QuadSpec& spec, const std::string& name, GltfBuilder builder = {}) {
  builder.addRootNode({{"mesh", pbr::test::addQuad(builder, spec)}});
  return builder.writeGltf(dir.path(), name);
}

// Every tangent is a unit vector perpendicular to its normal, with handedness +-1.
void checkTangentFrames(const pbr::MeshData& mesh) {
  size_t bad = 0;
  for (const pbr::Vertex& v : mesh.vertices) {
    const glm::vec3 t(v.tangent);
    const bool ok = std::abs(glm::length(t) - 1.0f) < 1e-3f &&
                    std::abs(glm::dot(t, glm::normalize(v.normal))) < 1e-3f && std::abs(v.tangent.w) == 1.0f;
    bad += ok ? 0 : 1;
  }
  CHECK(bad == 0);
}

}  // namespace

TEST_CASE("gltf assets: DamagedHelmet, Suzanne and BoxTextured load with their triangles, materials and textures") {
  for (const char* file : {"DamagedHelmet/glTF/DamagedHelmet.gltf", "DamagedHelmet/glTF-Binary/DamagedHelmet.glb"}) {
    CAPTURE(file);
    pbr::Scene scene;
    const pbr::Bounds b = pbr::appendGltf(scene, pbr::assetPath(file));
    CHECK(triangles(scene) == 15452);
    REQUIRE(scene.objects.size() == 1);
    const pbr::Material& m = scene.objects[0].material;
    // Every map of the metal-rough model; base colour and emissive are the sRGB ones.
    REQUIRE(m.baseColorTexture >= 0);
    REQUIRE(m.metallicRoughnessTexture >= 0);
    REQUIRE(m.normalTexture >= 0);
    REQUIRE(m.occlusionTexture >= 0);
    REQUIRE(m.emissiveTexture >= 0);
    CHECK(scene.textures.size() == 5);
    for (const pbr::TextureData& t : scene.textures) {
      CHECK(t.width == 2048);
      CHECK(t.height == 2048);
    }
    CHECK(scene.textures[static_cast<size_t>(m.baseColorTexture)].srgb);
    CHECK(scene.textures[static_cast<size_t>(m.emissiveTexture)].srgb);
    CHECK_FALSE(scene.textures[static_cast<size_t>(m.normalTexture)].srgb);
    CHECK_FALSE(scene.textures[static_cast<size_t>(m.metallicRoughnessTexture)].srgb);
    CHECK(m.emissive == glm::vec3(1.0f));
    // The file has no TANGENT: generated ones must form proper frames.
    checkTangentFrames(scene.meshes[static_cast<size_t>(scene.objects[0].mesh)]);
    // The node turns the Z-forward mesh by 90 degrees about X: mesh z in [-0.901, 0.901] becomes world y.
    CHECK(b.min.y == doctest::Approx(-0.901).epsilon(1e-3));
    CHECK(b.max.y == doctest::Approx(0.901).epsilon(1e-3));
  }

  pbr::Scene suzanne;
  pbr::appendGltf(suzanne, pbr::assetPath("Suzanne/glTF/Suzanne.gltf"));
  CHECK(triangles(suzanne) == 3936);
  REQUIRE(suzanne.objects.size() == 1);
  CHECK(suzanne.objects[0].material.baseColorTexture >= 0);
  CHECK(suzanne.objects[0].material.metallicRoughnessTexture >= 0);
  CHECK(suzanne.objects[0].material.normalTexture == -1);

  pbr::Scene box;
  pbr::appendGltf(box, pbr::assetPath("BoxTextured/glTF-Embedded/BoxTextured.gltf"));
  CHECK(triangles(box) == 12);
  REQUIRE(box.objects.size() == 1);
  REQUIRE(box.textures.size() == 1);
  const pbr::TextureData& t = box.textures[0];
  CHECK(t.srgb);
  CHECK(t.wrapS == 0x2901);  // REPEAT: the UVs reach 6
  CHECK(t.wrapT == 0x2901);
  CHECK(t.minFilter == 0x2702);  // NEAREST_MIPMAP_LINEAR as the file's sampler says
  CHECK(t.magFilter == 0x2601);
  float maxU = 0.0f;
  for (const pbr::Vertex& v : box.meshes[0].vertices) maxU = std::max(maxU, v.uv.x);
  CHECK(maxU == 6.0f);
  // The root node's matrix turns Z-up into Y-up: +Z goes to +Y, +Y to -Z.
  const glm::mat4& m = box.objects[0].transform;
  CHECK(glm::length(glm::vec3(m * glm::vec4(0, 0, 1, 0)) - glm::vec3(0, 1, 0)) < 1e-6f);
  CHECK(glm::length(glm::vec3(m * glm::vec4(0, 1, 0, 0)) - glm::vec3(0, 0, -1)) < 1e-6f);
}

TEST_CASE("gltf tangents: Suzanne's TANGENT attribute is used as stored") {
  // The test reads the accessor itself: Suzanne's tangents are tightly packed floats.
  const std::string path = pbr::assetPath("Suzanne/glTF/Suzanne.gltf");
  const json doc = json::parse(pbr::test::readFile(path));
  const json& prim = doc["meshes"][0]["primitives"][0];
  const json& accessor = doc["accessors"][prim["attributes"]["TANGENT"].get<int>()];
  const json& view = doc["bufferViews"][accessor["bufferView"].get<int>()];
  REQUIRE(view.value("byteStride", 16) == 16);
  const std::string bin =
      pbr::test::readFile(std::filesystem::path(path).parent_path() / doc["buffers"][0]["uri"].get<std::string>());
  const size_t offset = view.value("byteOffset", size_t(0)) + accessor.value("byteOffset", size_t(0));
  pbr::Scene scene;
  pbr::appendGltf(scene, path);
  const pbr::MeshData& mesh = scene.meshes[0];
  REQUIRE(mesh.vertices.size() == accessor["count"].get<size_t>());
  size_t same = 0;
  for (size_t i = 0; i < mesh.vertices.size(); ++i) {
    glm::vec4 stored;
    std::memcpy(&stored, bin.data() + offset + 16 * i, 16);
    same += mesh.vertices[i].tangent == stored ? 1 : 0;
  }
  CHECK(same == mesh.vertices.size());
}

TEST_CASE("gltf tangents: generated for a quad match the written ones, for upright, mirrored and rotated UVs") {
  const TempDir dir;
  const float c = std::cos(glm::radians(30.0f)), s = std::sin(glm::radians(30.0f));
  struct Case {
    const char* name;
    glm::mat2 uvFromXy;
    glm::vec4 tangent;  // along +u in the plane; w = +1 where +v runs down the image as seen from the front
  };
  const Case cases[] = {
      {"upright", glm::mat2(0.5f, 0.0f, 0.0f, -0.5f), {1, 0, 0, 1}},
      {"mirrored", glm::mat2(-0.5f, 0.0f, 0.0f, -0.5f), {-1, 0, 0, -1}},
      // The image turned by 30 degrees counter-clockwise and stretched: u grows along (c, s).
      // u = 0.5 (x, y).(c, s), v = 0.25 (x, y).(s, -c): the image turned 30 degrees counter-clockwise and
      // stretched, still upright.
      {"rotated", glm::mat2(0.5f * c, 0.25f * s, 0.5f * s, -0.25f * c), {c, s, 0, 1}},
      {"flipped v", glm::mat2(0.5f, 0.0f, 0.0f, 0.5f), {1, 0, 0, -1}},
  };
  for (const Case& k : cases) {
    CAPTURE(k.name);
    QuadSpec with;
    with.uvFromXy = k.uvFromXy;
    with.tangents = true;
    with.tangent = k.tangent;
    QuadSpec without = with;
    without.tangents = false;
    pbr::Scene a, b;
    pbr::appendGltf(a, quadFile(dir, with, std::string(k.name) + "_with"));
    pbr::appendGltf(b, quadFile(dir, without, std::string(k.name) + "_without"));
    REQUIRE(a.meshes.size() == 1);
    REQUIRE(b.meshes.size() == 1);
    for (size_t i = 0; i < 4; ++i) {
      CAPTURE(i);
      CHECK(a.meshes[0].vertices[i].tangent == k.tangent);  // read as written
      const glm::vec4 g = b.meshes[0].vertices[i].tangent;
      CHECK(degreesBetween(glm::vec3(g), glm::vec3(k.tangent)) < 0.1f);
      CHECK(g.w == k.tangent.w);
    }
  }
}

TEST_CASE("gltf geometry: node transforms compose, flat normals are generated, strips and fans become triangles") {
  const TempDir dir;
  GltfBuilder builder;
  QuadSpec spec;
  spec.normals = false;
  const int mesh = pbr::test::addQuad(builder, spec);
  // Parent: translate (1, 2, 3) and rotate 90 degrees about Y (quaternion x, y, z, w); child: scale 2 and a
  // matrix translation, so world = T R * M S.
  builder.doc["nodes"] = json::array(
      {{{"translation", {1, 2, 3}}, {"rotation", {0, std::sqrt(0.5), 0, std::sqrt(0.5)}}, {"children", {1}}},
       {{"mesh", mesh}, {"matrix", {2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0, 0, 0, 5, 1}}}});
  builder.doc["scenes"][0]["nodes"] = {0};
  const glm::mat4 outer = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, -1.0f, 0.0f));
  pbr::Scene scene;
  const pbr::Bounds bounds = pbr::appendGltf(scene, builder.writeGltf(dir.path(), "nodes"), outer);
  REQUIRE(scene.objects.size() == 1);
  const glm::mat4 expected = outer * glm::translate(glm::mat4(1.0f), glm::vec3(1, 2, 3)) *
                             glm::rotate(glm::mat4(1.0f), glm::radians(90.0f), glm::vec3(0, 1, 0)) *
                             glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, 5)) *
                             glm::scale(glm::mat4(1.0f), glm::vec3(2.0f));
  for (int col = 0; col < 4; ++col) CHECK(glm::length(scene.objects[0].transform[col] - expected[col]) < 1e-5f);
  // The quad spans x, y in [-2, 2] at z = 5 before the rotation, which takes z to x: x = 1 + 5, y = 2 - 1 +- 2.
  CHECK(bounds.min.x == doctest::Approx(6.0f));
  CHECK(bounds.max.x == doctest::Approx(6.0f));
  CHECK(bounds.min.y == doctest::Approx(-1.0f));
  CHECK(bounds.max.y == doctest::Approx(3.0f));
  // Without NORMAL every triangle gets its own vertices with the face normal.
  const pbr::MeshData& m = scene.meshes[0];
  CHECK(m.vertices.size() == 6);
  for (const pbr::Vertex& v : m.vertices) CHECK(v.normal == glm::vec3(0, 0, 1));

  for (const auto& [mode, indices, expectedTriangles] :
       {std::tuple<int, std::vector<uint32_t>, size_t>{5, {0, 1, 3, 2}, 2}, {6, {0, 1, 2, 3}, 2}}) {
    CAPTURE(mode);
    GltfBuilder b;
    const std::vector<float> positions = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0};
    const std::vector<float> normals = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
    b.addRootNode(
        {{"mesh", b.addMesh({{"attributes",
                              {{"POSITION", b.addFloats(positions, "VEC3")}, {"NORMAL", b.addFloats(normals, "VEC3")}}},
                             {"indices", b.addIndices(indices)},
                             {"mode", mode}})}});
    pbr::Scene s;
    pbr::appendGltf(s, b.writeGltf(dir.path(), "mode" + std::to_string(mode)));
    REQUIRE(s.meshes.size() == 1);
    const pbr::MeshData& sm = s.meshes[0];
    REQUIRE(sm.indices.size() == 3 * expectedTriangles);
    // Every triangle stays counter-clockwise seen from +Z, where the normals point.
    for (size_t t = 0; t < expectedTriangles; ++t) {
      const glm::vec3 p0 = sm.vertices[sm.indices[3 * t]].position, p1 = sm.vertices[sm.indices[3 * t + 1]].position,
                      p2 = sm.vertices[sm.indices[3 * t + 2]].position;
      CHECK(glm::cross(p1 - p0, p2 - p0).z > 0.0f);
    }
  }
}

TEST_CASE("gltf materials: factors, alpha modes, double-sided, emissive strength and the default material") {
  const TempDir dir;
  GltfBuilder builder;
  const int material = builder.addMaterial(
      {{"pbrMetallicRoughness",
        {{"baseColorFactor", {0.25, 0.5, 0.75, 0.4}}, {"metallicFactor", 0.3}, {"roughnessFactor", 0.7}}},
       {"emissiveFactor", {1.0, 0.5, 0.25}},
       {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 4.0}}}}},
       {"alphaMode", "MASK"},
       {"alphaCutoff", 0.3},
       {"doubleSided", true}});
  builder.doc["extensionsUsed"] = {"KHR_materials_emissive_strength"};
  builder.doc["extensionsRequired"] = {"KHR_materials_emissive_strength"};
  QuadSpec withMaterial;
  withMaterial.material = material;
  builder.addRootNode({{"mesh", pbr::test::addQuad(builder, withMaterial)}});
  builder.addRootNode({{"mesh", pbr::test::addQuad(builder, QuadSpec{})}});
  pbr::Scene scene;
  pbr::appendGltf(scene, builder.writeGltf(dir.path(), "materials"));
  REQUIRE(scene.objects.size() == 2);
  const pbr::Material& m = scene.objects[0].material;
  CHECK(m.baseColor == glm::vec3(0.25f, 0.5f, 0.75f));
  CHECK(m.alpha == 0.4f);
  CHECK(m.metalness == 0.3f);
  CHECK(m.roughness == 0.7f);
  CHECK(m.emissive == glm::vec3(4.0f, 2.0f, 1.0f));
  CHECK(m.alphaMode == pbr::AlphaMode::Mask);
  CHECK(m.alphaCutoff == 0.3f);
  CHECK(m.doubleSided);
  // glTF's default material: white, metallic 1, roughness 1, single-sided, opaque.
  const pbr::Material& d = scene.objects[1].material;
  CHECK(d.baseColor == glm::vec3(1.0f));
  CHECK(d.metalness == 1.0f);
  CHECK(d.roughness == 1.0f);
  CHECK(d.alphaMode == pbr::AlphaMode::Opaque);
  CHECK_FALSE(d.doubleSided);
}

TEST_CASE("gltf lights: KHR_lights_punctual point and directional lights with intensity as luminous power or lux") {
  const TempDir dir;
  GltfBuilder builder;
  builder.doc["extensionsUsed"] = {"KHR_lights_punctual"};
  builder.doc["extensions"]["KHR_lights_punctual"]["lights"] = {
      {{"type", "point"}, {"intensity", 10.0}, {"range", 5.0}, {"color", {1.0, 0.5, 0.25}}},
      {{"type", "point"}, {"intensity", 2.5}, {"color", {0.5, 0.8, 0.2}}},
      {{"type", "directional"}, {"intensity", 3.0}},
      {{"type", "directional"}, {"intensity", 100000.0}, {"color", {1.0, 0.9, 0.8}}}};
  // The second sun's node turns -Z by -90 degrees about X (quaternion x = -sin 45, w = cos 45): it shines down -Y.
  const double h = std::sqrt(0.5);
  builder.doc["nodes"] =
      json::array({{{"translation", {1, 2, 3}}, {"children", {1, 2}}},
                   {{"translation", {0, 1, 0}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}},
                   {{"translation", {0, 0, -4}}, {"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}},
                   {{"extensions", {{"KHR_lights_punctual", {{"light", 2}}}}}},
                   {{"rotation", {-h, 0, 0, h}}, {"extensions", {{"KHR_lights_punctual", {{"light", 3}}}}}}});
  builder.doc["scenes"][0]["nodes"] = {0, 3, 4};
  pbr::Scene scene;
  pbr::appendGltf(scene, builder.writeGltf(dir.path(), "lights"));
  REQUIRE(scene.lights.size() == 2);
  REQUIRE(scene.directionalLights.size() == 2);
  // A directional light shines along its node's -Z; its intensity is illuminance in lux.
  const pbr::DirectionalLight& sun = scene.directionalLights[0];
  CHECK(sun.direction == glm::vec3(0, 0, -1));
  CHECK(sun.illuminance == 3.0f);
  CHECK(sun.color == glm::vec3(1.0f));
  const pbr::DirectionalLight& turned = scene.directionalLights[1];
  CHECK(turned.direction.x == doctest::Approx(0.0).epsilon(1e-6));
  CHECK(turned.direction.y == doctest::Approx(-1.0));
  CHECK(turned.direction.z == doctest::Approx(0.0).scale(1.0).epsilon(1e-6));
  CHECK(turned.illuminance == 100000.0f);
  CHECK(turned.color == glm::vec3(1.0f, 0.9f, 0.8f));
  const pbr::PointLight& a = scene.lights[0];
  CHECK(a.position == glm::vec3(1, 3, 3));
  CHECK(a.luminousPower == doctest::Approx(4.0 * kPi * 10.0));  // P = 4 pi I
  CHECK(a.radius == 5.0f);
  CHECK(a.color == glm::vec3(1.0f, 0.5f, 0.25f));
  const pbr::PointLight& b = scene.lights[1];
  CHECK(b.position == glm::vec3(1, 2, -1));
  CHECK(b.luminousPower == doctest::Approx(4.0 * kPi * 2.5));
  // No range: the distance where I x (brightest channel) / d^2 falls to the stated cut-off illuminance.
  CHECK(b.radius == doctest::Approx(std::sqrt(2.5 * 0.8 / pbr::kGltfLightCutoffIlluminance)));
  CHECK(2.5f * 0.8f / (b.radius * b.radius) == doctest::Approx(pbr::kGltfLightCutoffIlluminance));
}

TEST_CASE("gltf cameras: cameras in node order, placed by their nodes and an absent zfar ends past the bounds") {
  const TempDir dir;
  GltfBuilder builder;
  builder.addRootNode({{"mesh", pbr::test::addQuad(builder, {})}});
  builder.doc["cameras"] = {
      {{"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.2}, {"zfar", 30.0}}}},
      {{"type", "orthographic"}, {"orthographic", {{"xmag", 1.0}, {"ymag", 1.0}, {"znear", 0.1}, {"zfar", 10.0}}}},
      {{"type", "perspective"}, {"perspective", {{"yfov", 1.0}, {"znear", 0.05}}}}};
  // The second perspective camera turns 90 degrees about +Y: it looks down -X.
  const double h = std::sqrt(0.5);
  builder.doc["nodes"].push_back({{"translation", {0, 0, 5}}, {"camera", 0}});
  builder.doc["nodes"].push_back({{"translation", {0, 1, 0}}, {"camera", 1}});
  builder.doc["nodes"].push_back({{"translation", {6, 0, 0}}, {"rotation", {0, h, 0, h}}, {"camera", 2}});
  builder.doc["scenes"][0]["nodes"] = {0, 1, 2, 3};
  const pbr::Scene scene = pbr::loadModelScene(builder.writeGltf(dir.path(), "cameras"));
  REQUIRE(scene.cameras.size() == 3);
  const pbr::Camera& a = scene.cameras[0];
  CHECK(a.position == glm::vec3(0, 0, 5));
  CHECK(a.target == glm::vec3(0, 0, 4));
  CHECK(a.up == glm::vec3(0, 1, 0));
  CHECK(a.fovYDeg == doctest::Approx(0.5 * 180.0 / kPi));
  CHECK(a.nearPlane == 0.2f);
  CHECK(a.farPlane == 30.0f);
  CHECK_FALSE(a.orthographic);
  const pbr::Camera& o = scene.cameras[1];
  CHECK(o.orthographic);
  CHECK(o.position == glm::vec3(0, 1, 0));
  CHECK(o.orthoHalfHeight == 1.0f);
  CHECK(o.nearPlane == 0.1f);
  CHECK(o.farPlane == 10.0f);
  const pbr::Camera& b = scene.cameras[2];
  CHECK(b.position == glm::vec3(6, 0, 0));
  CHECK(b.target.x == doctest::Approx(5.0));
  CHECK(b.target.z == doctest::Approx(0.0).epsilon(1e-6));
  // No zfar: the far plane lies just past the farthest corner of the quad's bounds, (-1, +-1, 0) at sqrt(50).
  CHECK(b.farPlane == doctest::Approx(std::sqrt(50.0) * 1.01).epsilon(1e-5));
  // The model's view is its first camera; the framing stays for --camera auto.
  CHECK(scene.camera.position == a.position);
  REQUIRE(scene.framedCamera.has_value());
  CHECK(scene.framedCamera->target == glm::vec3(0.0f));
}

TEST_CASE("gltf errors: malformed files give one line naming the file and the field") {
  const TempDir dir;
  const auto check = [](const std::string& message, const std::string& file, std::initializer_list<const char*> parts) {
    CAPTURE(message);
    CHECK(message.rfind(file + ": ", 0) == 0);
    CHECK(message.find('\n') == std::string::npos);
    for (const char* part : parts) CHECK(contains(message, part));
  };
  const auto quad = [](QuadSpec spec = {}) {
    GltfBuilder b;
    b.addRootNode({{"mesh", pbr::test::addQuad(b, spec)}});
    return b;
  };
  const auto load = [&](const GltfBuilder& b, const std::string& name) {
    const std::string path = b.writeGltf(dir.path(), name);
    CAPTURE(name);
    pbr::Scene scene;
    return std::make_pair(path, errorOf([&] { pbr::appendGltf(scene, path); }));
  };

  {
    GltfBuilder b = quad();
    b.doc["bufferViews"][2]["byteLength"] = 4096;
    const auto [path, message] = load(b, "view");
    check(message, path, {"bufferViews[2]", "byteOffset 80 + byteLength 4096 run past the end of buffers[0]"});
  }
  {
    GltfBuilder b = quad();
    b.doc["accessors"][1]["count"] = 5;  // TEXCOORD_0: 5 VEC2 elements in a 32-byte view
    const auto [path, message] = load(b, "accessor");
    check(message, path, {"accessors[1]", "bufferViews[1]"});
  }
  {
    GltfBuilder b = quad();
    b.doc["accessors"][0]["componentType"] = 5123;  // POSITION as UNSIGNED_SHORT
    const auto [path, message] = load(b, "component");
    check(message, path, {"attributes.POSITION", "UNSIGNED_SHORT"});
  }
  {
    GltfBuilder b = quad();
    const std::vector<uint32_t> bad = {0, 1, 2, 0, 2, 7};
    const int accessor = b.doc["meshes"][0]["primitives"][0]["indices"];
    const int view = b.doc["accessors"][accessor]["bufferView"];
    std::memcpy(b.bin.data() + b.doc["bufferViews"][view]["byteOffset"].get<size_t>(), bad.data(), 24);
    const auto [path, message] = load(b, "index");
    check(message, path, {"meshes[0].primitives[0].indices", "index 7", "4 vertices"});
  }
  {
    GltfBuilder b;
    QuadSpec spec;
    spec.material = b.addMaterial({{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}});
    b.doc["images"] = {{{"uri", "missing.png"}}};
    b.doc["textures"] = {{{"source", 0}}};
    b.addRootNode({{"mesh", pbr::test::addQuad(b, spec)}});
    // A missing image is drawn as a placeholder by default (tests/test_gltf_render.cpp); --strict refuses it.
    const std::string path = b.writeGltf(dir.path(), "image");
    pbr::Scene scene;
    check(errorOf([&] { pbr::appendGltf(scene, path, glm::mat4(1.0f), pbr::UriPolicy{false, true}); }), path,
          {"images[0].uri", "missing.png"});
  }
  {
    GltfBuilder b = quad();
    b.doc["extensionsUsed"] = {"KHR_texture_basisu"};
    b.doc["extensionsRequired"] = {"KHR_texture_basisu"};
    const auto [path, message] = load(b, "extension");
    check(message, path, {"extensionsRequired", "KHR_texture_basisu",
                          "no Debian package transcodes Basis Universal textures"});
  }
  {
    // A buffer without a URI that only an unsupported required extension could explain: the extension is checked
    // first, so it is what the message names.
    GltfBuilder b = quad();
    b.doc["buffers"] = {json::object(), {{"byteLength", 1024}}};
    b.doc["extensionsUsed"] = b.doc["extensionsRequired"] = {"KHR_texture_basisu"};
    const auto [path, message] = load(b, "basisu");
    check(message, path, {"extensionsRequired", "KHR_texture_basisu"});
    CHECK(message.find("buffers") == std::string::npos);
  }
  {
    GltfBuilder b = quad();
    b.doc["nodes"][0]["children"] = {0};
    const auto [path, message] = load(b, "cycle");
    check(message, path, {"nodes[0]"});
  }
  {
    const std::string path = (dir.path() / "not_json.gltf").string();
    std::ofstream(path) << "{ this is not json";
    pbr::Scene scene;
    const std::string message = errorOf([&] { pbr::appendGltf(scene, path); });
    CHECK(message.rfind(path + ":1:4: JSON syntax error: ", 0) == 0);  // at the "h" of "this"
  }
  {
    // nlohmann reports a number beyond double range without a location; the loader names line, column and path.
    GltfBuilder b = quad();
    const std::string path = b.writeGltf(dir.path(), "overflow");
    std::string text = pbr::test::readFile(path);
    const std::string key = R"("translation":[1e999,0,0],)";
    text.insert(text.find(R"("mesh")"), key);
    std::ofstream(path) << text;
    pbr::Scene scene;
    const std::string message = errorOf([&] { pbr::appendGltf(scene, path); });
    CAPTURE(message);
    CHECK(message.rfind(path + ":", 0) == 0);
    CHECK(message.find(": nodes[0].translation[0]: expected a finite number, got 1e999") != std::string::npos);
  }
  {
    const std::string path = (dir.path() / "absent.gltf").string();
    pbr::Scene scene;
    check(errorOf([&] { pbr::appendGltf(scene, path); }), path, {"cannot open"});
  }
}

TEST_CASE("gltf errors: extreme values in every index, offset and count are rejected or loaded, never read wildly") {
  // Under AddressSanitizer (make sanitize) any read outside a buffer fails this test.
  const TempDir dir;
  GltfBuilder base;
  QuadSpec spec;
  spec.tangents = true;
  base.addRootNode({{"mesh", pbr::test::addQuad(base, spec)}});
  const std::vector<json> values = {-1,           0, 1, 3, 7, 255, 65536, 2147483647, 4294967295u, 1099511627776ull,
                                    -4294967296ll};
  int variant = 0, rejected = 0;
  const auto attempt = [&](const GltfBuilder& b, bool glb) {
    const std::string name = "v" + std::to_string(variant++);
    const std::string path = glb ? b.writeGlb(dir.path(), name) : b.writeGltf(dir.path(), name);
    pbr::Scene scene;
    try {
      pbr::appendGltf(scene, path);
    } catch (const pbr::SceneError& e) {
      ++rejected;
      CHECK(std::string(e.what()).rfind(path + ": ", 0) == 0);
    }
  };
  const auto mutate = [&](const char* array, const char* field) {
    for (size_t i = 0; i < base.doc[array].size(); ++i) {
      for (const json& v : values) {
        GltfBuilder b = base;
        b.doc[array][i][field] = v;
        attempt(b, (variant % 2) == 1);
      }
    }
  };
  for (const char* f : {"bufferView", "byteOffset", "count", "componentType"}) mutate("accessors", f);
  for (const char* f : {"buffer", "byteOffset", "byteLength", "byteStride"}) mutate("bufferViews", f);
  for (const char* f : {"mesh"}) mutate("nodes", f);
  for (const json& v : values) {
    GltfBuilder b = base;
    b.doc["meshes"][0]["primitives"][0]["indices"] = v;
    attempt(b, false);
    b = base;
    b.doc["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = v;
    attempt(b, true);
    b = base;
    b.doc["scenes"][0]["nodes"] = {v};
    attempt(b, false);
  }
  MESSAGE(variant << " variants, " << rejected << " rejected");
  CHECK(rejected > variant / 2);
}

TEST_CASE("gltf assets: PBR_ASSET_DIR moves the asset folder, and a missing asset is one line naming its path") {
  const TempDir dir;
  const char* previous = std::getenv("PBR_ASSET_DIR");
  const std::string saved = previous ? previous : "";
  ::setenv("PBR_ASSET_DIR", dir.path().c_str(), 1);
  const std::string expected = (dir.path() / "DamagedHelmet/glTF-Binary/DamagedHelmet.glb").string();
  const std::string message = errorOf([] { pbr::makeBuiltinScene("helmet"); });
  // The scene file names the model "asset:...", so the message leads with the file and field that did.
  const std::string scene = pbr::builtinSceneDir() + "/helmet.json";
  CHECK(message.rfind(scene + ": objects[0].gltf: " + expected + ": asset not found", 0) == 0);
  CHECK(message.find('\n') == std::string::npos);
  std::ofstream(dir.path() / "present.txt") << "x";
  CHECK(pbr::assetPath("present.txt") == (dir.path() / "present.txt").string());
  if (previous) {
    ::setenv("PBR_ASSET_DIR", saved.c_str(), 1);
  } else {
    ::unsetenv("PBR_ASSET_DIR");
  }
}

TEST_CASE("gltf sparse accessors: pairs replace the base's elements, over a view or zeros, and bad pairs are refused") {
  const TempDir dir;
  // The quad's corners, and the same positions as a sparse accessor: over a view holding them with two corners
  // moved away (the pairs move them back), and over zeros (no view: the pairs set all four).
  GltfBuilder plain = pbr::test::quadModel();
  const int positions = plain.doc["meshes"][0]["primitives"][0]["attributes"]["POSITION"];
  const pbr::Scene expected = [&] {
    pbr::Scene s;
    pbr::appendGltf(s, plain.writeGltf(dir.path(), "plain"));
    return s;
  }();
  REQUIRE(expected.meshes.size() == 1);
  const std::vector<pbr::Vertex>& corners = expected.meshes[0].vertices;
  REQUIRE(corners.size() == 4);
  const auto sparse = [&](bool overView, std::vector<uint16_t> indices, const std::string& name) {
    GltfBuilder b = plain;
    json& accessor = b.doc["accessors"][positions];
    std::vector<float> values;
    for (const uint16_t i : indices) {
      const glm::vec3 p = corners[i < 4 ? i : 0].position;
      values.insert(values.end(), {p.x, p.y, p.z});
    }
    if (overView) {
      std::vector<float> moved;
      for (size_t i = 0; i < 4; ++i) {
        const glm::vec3 p = corners[i].position + (i == 1 || i == 3 ? glm::vec3(5.0f) : glm::vec3(0.0f));
        moved.insert(moved.end(), {p.x, p.y, p.z});
      }
      accessor["bufferView"] = b.addView(moved.data(), moved.size() * sizeof(float));
    } else {
      accessor.erase("bufferView");
    }
    const int indexView = b.addView(indices.data(), indices.size() * sizeof(uint16_t));
    const int valueView = b.addView(values.data(), values.size() * sizeof(float));
    accessor["sparse"] = {{"count", indices.size()},
                          {"indices", {{"bufferView", indexView}, {"componentType", 5123}}},
                          {"values", {{"bufferView", valueView}}}};
    return b.writeGltf(dir.path(), name);
  };
  for (const auto& [path, label] : {std::make_pair(sparse(true, {1, 3}, "over_view"), "over a view"),
                                    std::make_pair(sparse(false, {0, 1, 2, 3}, "over_zeros"), "over zeros")}) {
    CAPTURE(label);
    pbr::Scene s;
    pbr::appendGltf(s, path);
    REQUIRE(s.meshes.size() == 1);
    REQUIRE(s.meshes[0].vertices.size() == 4);
    for (size_t i = 0; i < 4; ++i) CHECK(s.meshes[0].vertices[i].position == corners[i].position);
  }
  // An index past the accessor's elements, and pairs running past their views.
  const std::string outOfRange = sparse(true, {1, 4}, "out_of_range");
  CHECK(errorOf([&] { pbr::Scene s; pbr::appendGltf(s, outOfRange); }) ==
        outOfRange + ": accessors[" + std::to_string(positions) +
            "].sparse.indices: index 4 at position 1 is out of range (the accessor has 4 elements)");
  {
    const std::string path = sparse(true, {1, 3}, "long");
    json doc = json::parse(pbr::test::readFile(path));
    doc["accessors"][positions]["sparse"]["count"] = 3;
    std::ofstream(path) << doc.dump();
    const std::string message = errorOf([&] { pbr::Scene s; pbr::appendGltf(s, path); });
    CHECK(contains(message, ".sparse.indices: 3 elements of 2 bytes from byteOffset 0 run past the end"));
  }
  // The Khronos sample (microsoft/glTF-SDK's copy) raises three of its fourteen vertices, (1, 1), (3, 1) and (5, 1),
  // to (1, 2), (3, 3) and (5, 4); without normals its triangles get their own vertices.
  const std::filesystem::path sample =
      std::filesystem::path(pbr::assetDir()) / "exports/sdk-SimpleSparseAccessor/SimpleSparseAccessor.gltf";
  if (std::filesystem::exists(sample)) {
    pbr::Scene s;
    pbr::appendGltf(s, sample.string());
    REQUIRE(s.meshes.size() == 1);
    const auto has = [&](float x, float y) {
      return std::any_of(s.meshes[0].vertices.begin(), s.meshes[0].vertices.end(),
                         [&](const pbr::Vertex& v) { return v.position == glm::vec3(x, y, 0.0f); });
    };
    CHECK(has(1.0f, 2.0f));
    CHECK(has(3.0f, 3.0f));
    CHECK(has(5.0f, 4.0f));
    CHECK_FALSE(has(1.0f, 1.0f));
    CHECK_FALSE(has(3.0f, 1.0f));
    CHECK_FALSE(has(5.0f, 1.0f));
    CHECK(has(2.0f, 1.0f));
  }
}

TEST_CASE("gltf leniency: an unused accessor of count 0 is read as empty, and refused with --strict") {
  // As Obj2GltfConverter writes one (shared/assets/exports/jl-Astronaut_obj2gltfconverter).
  const TempDir dir;
  GltfBuilder b = pbr::test::quadModel();
  const size_t empty = b.doc["accessors"].size();
  b.doc["accessors"].push_back({{"bufferView", 0}, {"componentType", 5126}, {"count", 0}, {"type", "VEC3"}});
  const std::string path = b.writeGltf(dir.path(), "empty_accessor");
  pbr::Scene lenient;
  pbr::appendGltf(lenient, path);
  CHECK(lenient.objects.size() == 1);
  pbr::Scene strict;
  CHECK(errorOf([&] { pbr::appendGltf(strict, path, glm::mat4(1.0f), pbr::UriPolicy{false, true}); }) ==
        path + ": accessors[" + std::to_string(empty) + "].count: must be an integer in [1, 2147483648] (got 0)");
}

TEST_CASE("gltf KHR_mesh_quantization: integer positions, normals and UVs load as the float quad they encode") {
  const TempDir dir;
  GltfBuilder plain = pbr::test::quadModel();
  pbr::Scene expected;
  pbr::appendGltf(expected, plain.writeGltf(dir.path(), "plain"));
  REQUIRE(expected.meshes.size() == 1);
  const std::vector<pbr::Vertex>& v = expected.meshes[0].vertices;
  REQUIRE(v.size() == 4);
  // SHORT positions (the corners are whole numbers), normalized BYTE normals, normalized UNSIGNED_SHORT UVs (0 or 1).
  std::vector<int16_t> positions;
  std::vector<int8_t> normals;
  std::vector<uint16_t> uvs;
  for (const pbr::Vertex& p : v) {
    for (int c = 0; c < 3; ++c) positions.push_back(static_cast<int16_t>(p.position[c]));
    positions.push_back(0);  // each element padded to 4 bytes, as the specification aligns vertex attributes
    for (int c = 0; c < 3; ++c) normals.push_back(static_cast<int8_t>(127.0f * p.normal[c]));
    normals.push_back(0);
    for (int c = 0; c < 2; ++c) uvs.push_back(static_cast<uint16_t>(65535.0f * p.uv[c]));
  }
  GltfBuilder q = plain;
  json& attributes = q.doc["meshes"][0]["primitives"][0]["attributes"];
  const auto add = [&](const void* data, size_t bytes, int componentType, bool normalized, const char* type,
                       size_t stride) {
    const int view = q.addView(data, bytes);
    q.doc["bufferViews"][view]["byteStride"] = stride;
    json accessor = {{"bufferView", view}, {"componentType", componentType}, {"count", 4}, {"type", type}};
    if (normalized) accessor["normalized"] = true;
    q.doc["accessors"].push_back(accessor);
    return static_cast<int>(q.doc["accessors"].size()) - 1;
  };
  attributes["POSITION"] = add(positions.data(), positions.size() * 2, 5122, false, "VEC3", 8);
  q.doc["accessors"][attributes["POSITION"].get<int>()]["min"] = {-1, -1, 0};
  q.doc["accessors"][attributes["POSITION"].get<int>()]["max"] = {1, 1, 0};
  attributes["NORMAL"] = add(normals.data(), normals.size(), 5120, true, "VEC3", 4);
  attributes["TEXCOORD_0"] = add(uvs.data(), uvs.size() * 2, 5123, true, "VEC2", 4);
  // Without the extension the integer positions are refused; with it they load.
  const std::string undeclared = q.writeGltf(dir.path(), "undeclared");
  const std::string message = errorOf([&] {
    pbr::Scene s;
    pbr::appendGltf(s, undeclared);
  });
  CHECK(contains(message, "meshes[0].primitives[0].attributes.POSITION: accessors["));
  CHECK(contains(message, "has componentType SHORT, expected FLOAT"));
  q.doc["extensionsUsed"] = q.doc["extensionsRequired"] = {"KHR_mesh_quantization"};
  pbr::Scene s;
  pbr::appendGltf(s, q.writeGltf(dir.path(), "quantized"));
  REQUIRE(s.meshes.size() == 1);
  REQUIRE(s.meshes[0].vertices.size() == 4);
  for (size_t i = 0; i < 4; ++i) {
    CAPTURE(i);
    CHECK(s.meshes[0].vertices[i].position == v[i].position);
    CHECK(glm::length(s.meshes[0].vertices[i].normal - v[i].normal) < 1e-6f);
    CHECK(s.meshes[0].vertices[i].uv == v[i].uv);
  }
}

TEST_CASE("gltf EXT_mesh_gpu_instancing: every instance drawn, placed by its TRS after the node's transform") {
  const TempDir dir;
  GltfBuilder b = pbr::test::quadModel();
  const float s = std::sqrt(0.5f);
  // Four instances: moved, turned a quarter about +Z, scaled by 2, and one scaled to nothing (hidden).
  const std::vector<float> translations = {0, 0, 0, 2, 0, 0, 0, 3, 0, 5, 5, 5};
  const std::vector<float> rotations = {0, 0, 0, 1, 0, 0, s, s, 0, 0, 0, 1, 0, 0, 0, 1};
  const std::vector<float> scales = {1, 1, 1, 1, 1, 1, 2, 2, 2, 0, 0, 0};
  const json attributes = {{"TRANSLATION", b.addFloats(translations, "VEC3")},
                           {"ROTATION", b.addFloats(rotations, "VEC4")},
                           {"SCALE", b.addFloats(scales, "VEC3")}};
  b.doc["nodes"][0]["translation"] = {10.0, 0.0, 0.0};
  b.doc["nodes"][0]["extensions"]["EXT_mesh_gpu_instancing"]["attributes"] = attributes;
  b.doc["extensionsUsed"] = {"EXT_mesh_gpu_instancing"};
  pbr::Scene scene;
  pbr::appendGltf(scene, b.writeGltf(dir.path(), "instanced"));
  REQUIRE(scene.objects.size() == 3);
  const glm::mat4 node = glm::translate(glm::mat4(1.0f), {10.0f, 0.0f, 0.0f});
  const glm::mat4 expected[] = {
      node, node * glm::translate(glm::mat4(1.0f), {2.0f, 0.0f, 0.0f}) *
                glm::rotate(glm::mat4(1.0f), glm::radians(90.0f), {0.0f, 0.0f, 1.0f}),
      node * glm::translate(glm::mat4(1.0f), {0.0f, 3.0f, 0.0f}) * glm::scale(glm::mat4(1.0f), glm::vec3(2.0f))};
  for (size_t i = 0; i < 3; ++i) {
    CAPTURE(i);
    for (int c = 0; c < 4; ++c) {
      for (int r = 0; r < 4; ++r) CHECK(scene.objects[i].transform[c][r] == doctest::Approx(expected[i][c][r]));
    }
    CHECK(scene.objects[i].mesh == scene.objects[0].mesh);  // one mesh, drawn three times
  }
  // Attributes of different counts are refused, naming the extension.
  b.doc["nodes"][0]["extensions"]["EXT_mesh_gpu_instancing"]["attributes"]["SCALE"] =
      b.addFloats({1, 1, 1, 1, 1, 1}, "VEC3");
  const std::string path = b.writeGltf(dir.path(), "mismatched");
  CHECK(errorOf([&] {
          pbr::Scene s2;
          pbr::appendGltf(s2, path);
        }) == path + ": nodes[0].extensions.EXT_mesh_gpu_instancing.attributes: TRANSLATION, ROTATION and SCALE "
                     "must have as many elements as each other");
}

TEST_CASE("gltf EXT_texture_webp: the WebP source replaces the fallback, and decodes to the pixels it encodes") {
  const TempDir dir;
  pbr::ImageRgba8 image{4, 2, {}};
  for (int i = 0; i < 8; ++i) {
    const auto byte = [](int v) { return static_cast<unsigned char>(v); };
    image.pixels.insert(image.pixels.end(), {byte(30 * i), 200, byte(i), 255});
  }
  uint8_t* encoded = nullptr;
  const size_t size = WebPEncodeLosslessRGBA(image.pixels.data(), image.width, image.height, image.width * 4, &encoded);
  REQUIRE(size > 0);
  std::ofstream(dir.path() / "texture.webp", std::ios::binary).write(reinterpret_cast<const char*>(encoded),
                                                                    static_cast<std::streamsize>(size));
  WebPFree(encoded);
  GltfBuilder b;
  // The fallback PNG is another picture: the WebP one must be the one drawn.
  const int texture = b.addPngTexture(dir.path(), "fallback.png", pbr::test::solidImage(2, 2, {9, 9, 9, 255}));
  b.doc["images"].push_back({{"uri", "texture.webp"}, {"mimeType", "image/webp"}});
  b.doc["textures"][texture]["extensions"]["EXT_texture_webp"]["source"] = 1;
  b.doc["extensionsUsed"] = b.doc["extensionsRequired"] = {"EXT_texture_webp"};
  QuadSpec spec;
  spec.material = b.addMaterial({{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", texture}}}}}});
  b.addRootNode({{"mesh", pbr::test::addQuad(b, spec)}});
  pbr::Scene scene;
  pbr::appendGltf(scene, b.writeGltf(dir.path(), "webp"));
  REQUIRE(scene.textures.size() == 1);
  CHECK(scene.textures[0].width == 4);
  CHECK(scene.textures[0].rgba == image.pixels);
}

TEST_CASE("gltf KHR_draco_mesh_compression: a Draco-compressed quad loads as the triangles of the plain one") {
  const TempDir dir;
  GltfBuilder plain = pbr::test::quadModel();
  pbr::Scene expected;
  pbr::appendGltf(expected, plain.writeGltf(dir.path(), "plain"));
  const pbr::MeshData& quad = expected.meshes.at(0);
  // The same triangles through Draco (no quantization: the values come back exactly).
  draco::TriangleSoupMeshBuilder builder;
  builder.Start(static_cast<int>(quad.indices.size() / 3));
  const int position = builder.AddAttribute(draco::GeometryAttribute::POSITION, 3, draco::DT_FLOAT32);
  const int normal = builder.AddAttribute(draco::GeometryAttribute::NORMAL, 3, draco::DT_FLOAT32);
  const int uv = builder.AddAttribute(draco::GeometryAttribute::TEX_COORD, 2, draco::DT_FLOAT32);
  for (size_t f = 0; f < quad.indices.size() / 3; ++f) {
    const pbr::Vertex* v[3];
    for (size_t k = 0; k < 3; ++k) v[k] = &quad.vertices[quad.indices[3 * f + k]];
    const draco::FaceIndex face(static_cast<uint32_t>(f));
    builder.SetAttributeValuesForFace(position, face, &v[0]->position, &v[1]->position, &v[2]->position);
    builder.SetAttributeValuesForFace(normal, face, &v[0]->normal, &v[1]->normal, &v[2]->normal);
    builder.SetAttributeValuesForFace(uv, face, &v[0]->uv, &v[1]->uv, &v[2]->uv);
  }
  const std::unique_ptr<draco::Mesh> mesh = builder.Finalize();
  REQUIRE(mesh);
  draco::EncoderBuffer encoded;
  draco::Encoder encoder;
  REQUIRE(encoder.EncodeMeshToBuffer(*mesh, &encoded).ok());

  GltfBuilder b;
  const int view = b.addView(encoded.data(), encoded.size());
  const auto accessor = [&](const char* type, int componentType, size_t count) {
    b.doc["accessors"].push_back({{"componentType", componentType}, {"count", count}, {"type", type}});
    return static_cast<int>(b.doc["accessors"].size()) - 1;
  };
  const size_t points = mesh->num_points();
  const int positions = accessor("VEC3", 5126, points);
  b.doc["accessors"][positions]["min"] = {-1, -1, 0};
  b.doc["accessors"][positions]["max"] = {1, 1, 0};
  b.addRootNode({{"mesh", b.addMesh({{"attributes",
                                      {{"POSITION", positions},
                                       {"NORMAL", accessor("VEC3", 5126, points)},
                                       {"TEXCOORD_0", accessor("VEC2", 5126, points)}}},
                                     {"indices", accessor("SCALAR", 5125, quad.indices.size())},
                                     {"extensions",
                                      {{"KHR_draco_mesh_compression",
                                        {{"bufferView", view},
                                         {"attributes",
                                          {{"POSITION", mesh->attribute(position)->unique_id()},
                                           {"NORMAL", mesh->attribute(normal)->unique_id()},
                                           {"TEXCOORD_0", mesh->attribute(uv)->unique_id()}}}}}}}})}});
  b.doc["extensionsUsed"] = b.doc["extensionsRequired"] = {"KHR_draco_mesh_compression"};
  for (const bool glb : {false, true}) {
    CAPTURE(glb);
    pbr::Scene scene;
    pbr::appendGltf(scene, glb ? b.writeGlb(dir.path(), "draco") : b.writeGltf(dir.path(), "draco"));
    REQUIRE(scene.meshes.size() == 1);
    const pbr::MeshData& got = scene.meshes[0];
    REQUIRE(got.indices.size() == quad.indices.size());
    // Draco orders the triangles, and the corners within each, its own way (keeping the winding): each decoded
    // triangle is one of the plain quad's, turned, with the same positions, normals and UVs at its corners.
    std::vector<bool> matched(quad.indices.size() / 3, false);
    for (size_t f = 0; f < got.indices.size() / 3; ++f) {
      bool found = false;
      for (size_t e = 0; e < matched.size() && !found; ++e) {
        for (size_t turn = 0; turn < 3 && !found; ++turn) {
          bool same = !matched[e];
          for (size_t k = 0; k < 3 && same; ++k) {
            const pbr::Vertex& g = got.vertices[got.indices[3 * f + k]];
            const pbr::Vertex& x = quad.vertices[quad.indices[3 * e + (k + turn) % 3]];
            same = g.position == x.position && g.normal == x.normal && g.uv == x.uv;
          }
          if (same) matched[e] = found = true;
        }
      }
      CAPTURE(f);
      CHECK(found);
    }
  }
}

TEST_CASE("gltf EXT_meshopt_compression: compressed views beside a data-less fallback buffer load as the plain quad") {
  const TempDir dir;
  GltfBuilder plain = pbr::test::quadModel();
  pbr::Scene expected;
  pbr::appendGltf(expected, plain.writeGltf(dir.path(), "plain"));
  const pbr::MeshData& quad = expected.meshes.at(0);
  std::vector<float> positions, normals, uvs;
  for (const pbr::Vertex& v : quad.vertices) {
    positions.insert(positions.end(), {v.position.x, v.position.y, v.position.z});
    normals.insert(normals.end(), {v.normal.x, v.normal.y, v.normal.z});
    uvs.insert(uvs.end(), {v.uv.x, v.uv.y});
  }
  const size_t count = quad.vertices.size();
  GltfBuilder b;
  size_t fallbackLength = 0;
  std::vector<size_t> streamOffsets;  // where each compressed stream lies in buffer 0
  // A view of the fallback buffer (buffer 1, no data) whose bytes are decoded from compressed ones in buffer 0.
  const auto compressed = [&](const std::vector<unsigned char>& bytes, size_t elements, size_t stride,
                              const char* mode, bool attribute) {
    // addView puts the compressed bytes in buffer 0; the view it made becomes the fallback buffer's view.
    const int source = b.addView(bytes.data(), bytes.size());
    const size_t sourceOffset = b.doc["bufferViews"][source]["byteOffset"];
    streamOffsets.push_back(sourceOffset);
    json view = {{"buffer", 1},
                 {"byteOffset", fallbackLength},
                 {"byteLength", elements * stride},
                 {"extensions",
                  {{"EXT_meshopt_compression",
                    {{"buffer", 0},
                     {"byteOffset", sourceOffset},
                     {"byteLength", bytes.size()},
                     {"byteStride", stride},
                     {"count", elements},
                     {"mode", mode}}}}}};
    if (attribute) view["byteStride"] = stride;
    fallbackLength += (elements * stride + 3) / 4 * 4;
    b.doc["bufferViews"][source] = view;
    return source;
  };
  const auto vertexStream = [&](const std::vector<float>& values, size_t stride) {
    std::vector<unsigned char> out(meshopt_encodeVertexBufferBound(count, stride));
    out.resize(meshopt_encodeVertexBuffer(out.data(), out.size(), values.data(), count, stride));
    return out;
  };
  std::vector<unsigned char> indexStream(meshopt_encodeIndexBufferBound(quad.indices.size(), count));
  indexStream.resize(
      meshopt_encodeIndexBuffer(indexStream.data(), indexStream.size(), quad.indices.data(), quad.indices.size()));
  const auto accessor = [&](int view, const char* type, int componentType, size_t elements) {
    b.doc["accessors"].push_back(
        {{"bufferView", view}, {"componentType", componentType}, {"count", elements}, {"type", type}});
    return static_cast<int>(b.doc["accessors"].size()) - 1;
  };
  const int p = accessor(compressed(vertexStream(positions, 12), count, 12, "ATTRIBUTES", true), "VEC3", 5126, count);
  b.doc["accessors"][p]["min"] = {-1, -1, 0};
  b.doc["accessors"][p]["max"] = {1, 1, 0};
  const int n = accessor(compressed(vertexStream(normals, 12), count, 12, "ATTRIBUTES", true), "VEC3", 5126, count);
  const int t = accessor(compressed(vertexStream(uvs, 8), count, 8, "ATTRIBUTES", true), "VEC2", 5126, count);
  const int i = accessor(compressed(indexStream, quad.indices.size(), 4, "TRIANGLES", false), "SCALAR", 5125,
                         quad.indices.size());
  b.doc["buffers"] = {json::object(),
                      {{"byteLength", fallbackLength},
                       {"extensions", {{"EXT_meshopt_compression", {{"fallback", true}}}}}}};
  b.addRootNode({{"mesh", b.addMesh({{"attributes", {{"POSITION", p}, {"NORMAL", n}, {"TEXCOORD_0", t}}},
                                     {"indices", i}})}});
  b.doc["extensionsUsed"] = b.doc["extensionsRequired"] = {"EXT_meshopt_compression"};
  for (const bool glb : {false, true}) {
    CAPTURE(glb);
    pbr::Scene scene;
    pbr::appendGltf(scene, glb ? b.writeGlb(dir.path(), "meshopt") : b.writeGltf(dir.path(), "meshopt"));
    REQUIRE(scene.meshes.size() == 1);
    const pbr::MeshData& got = scene.meshes[0];
    CHECK(got.indices == quad.indices);
    REQUIRE(got.vertices.size() == count);
    for (size_t k = 0; k < count; ++k) {
      CHECK(got.vertices[k].position == quad.vertices[k].position);
      CHECK(got.vertices[k].normal == quad.vertices[k].normal);
      CHECK(got.vertices[k].uv == quad.vertices[k].uv);
    }
  }
  // Compressed bytes that do not decode are refused by name: the positions' stream with its header byte, which
  // names the codec version, spoilt.
  b.bin[streamOffsets.front()] ^= 0xFF;
  const std::string broken = b.writeGltf(dir.path(), "broken");
  const std::string message = errorOf([&] {
    pbr::Scene s;
    pbr::appendGltf(s, broken);
  });
  CHECK(contains(message, ".extensions.EXT_meshopt_compression: the compressed data does not decode"));
}

TEST_CASE("gltf errors: an asset of another glTF version, and a required extension that is no name, are refused") {
  const TempDir dir;
  struct Case {
    std::string key;
    json value;
    std::string message;
  };
  const std::vector<Case> cases = {
      {"version", "1.0", "asset.version: \"1.0\" is not a glTF version this loader reads (2.0)"},
      {"version", "3.0", "asset.version: \"3.0\" is not a glTF version this loader reads (2.0)"},
      {"version", "two", "asset.version: \"two\" is not a version like \"2.0\""},
      {"minVersion", "2.1", "asset.minVersion: \"2.1\" is not a glTF version this loader reads (2.0)"},
  };
  for (const Case& c : cases) {
    CAPTURE(c.message);
    GltfBuilder b = pbr::test::quadModel();
    b.doc["asset"][c.key] = c.value;
    const std::string path = b.writeGltf(dir.path(), "version");
    CHECK(errorOf([&] {
            pbr::Scene s;
            pbr::appendGltf(s, path);
          }) == path + ": " + c.message);
  }
  // A later minor version without a minVersion loads (glTF 2.0, 3.2).
  GltfBuilder later = pbr::test::quadModel();
  later.doc["asset"]["version"] = "2.1";
  pbr::Scene s;
  pbr::appendGltf(s, later.writeGltf(dir.path(), "later"));
  CHECK(s.objects.size() == 1);
  GltfBuilder number = pbr::test::quadModel();
  number.doc["extensionsRequired"] = {5};
  const std::string path = number.writeGltf(dir.path(), "number");
  CHECK(errorOf([&] {
          pbr::Scene t;
          pbr::appendGltf(t, path);
        }) == path + ": extensionsRequired[0]: must be an extension name (got 5)");
}

TEST_CASE("gltf errors: a material value of the wrong form is refused by name, not the material dropped") {
  const TempDir dir;
  const std::string pbr = "materials[0].pbrMetallicRoughness.";
  const std::vector<std::tuple<json, std::string>> cases = {
      {{{"pbrMetallicRoughness", {{"baseColorFactor", {1, 0, 0}}}}},
       pbr + "baseColorFactor: must be an array of 4 numbers (got [1,0,0])"},
      {{{"pbrMetallicRoughness", {{"roughnessFactor", "0.5"}}}},
       pbr + "roughnessFactor: must be a number (got \"0.5\")"},
      {{{"emissiveFactor", {1, 1}}}, "materials[0].emissiveFactor: must be an array of 3 numbers (got [1,1])"},
      {{{"doubleSided", "yes"}}, "materials[0].doubleSided: must be true or false (got \"yes\")"},
      {{{"alphaCutoff", {0.5}}}, "materials[0].alphaCutoff: must be a number (got [0.5])"},
  };
  int n = 0;
  for (const auto& [material, message] : cases) {
    CAPTURE(message);
    GltfBuilder b;
    QuadSpec spec;
    spec.material = b.addMaterial(material);
    b.addRootNode({{"mesh", pbr::test::addQuad(b, spec)}});
    const std::string path = b.writeGltf(dir.path(), "material" + std::to_string(n++));
    CHECK(errorOf([&] {
            pbr::Scene s;
            pbr::appendGltf(s, path);
          }) == path + ": " + message);
  }
}

TEST_CASE("gltf materials: KHR_materials_ior and KHR_materials_specular's factors and maps") {
  const TempDir dir;
  GltfBuilder builder;
  const int map = builder.addPngTexture(dir.path(), "map.png", {2, 2, std::vector<uint8_t>(16, 200)});
  const int material = builder.addMaterial(
      {{"extensions",
        {{"KHR_materials_ior", {{"ior", 1.33}}},
         {"KHR_materials_specular",
          {{"specularFactor", 0.5},
           {"specularColorFactor", {2.0, 1.0, 0.5}},
           {"specularTexture", {{"index", map}}},
           {"specularColorTexture",
            {{"index", map}, {"extensions", {{"KHR_texture_transform", {{"scale", {2.0, 2.0}}}}}}}}}}}}});
  builder.doc["extensionsUsed"] = {"KHR_materials_ior", "KHR_materials_specular"};
  QuadSpec withMaterial;
  withMaterial.material = material;
  builder.addRootNode({{"mesh", pbr::test::addQuad(builder, withMaterial)}});
  pbr::Scene scene;
  const pbr::test::CapturedStderr warnings;
  pbr::appendGltf(scene, builder.writeGltf(dir.path(), "specular"));
  REQUIRE(scene.objects.size() == 1);
  const pbr::Material& m = scene.objects[0].material;
  CHECK(m.ior == 1.33f);
  CHECK(m.specular == 0.5f);
  CHECK(m.specularColor == glm::vec3(2.0f, 1.0f, 0.5f));
  // The strength map linear, the colour map sRGB: one image, two textures; the colour's transform read.
  REQUIRE(m.specularMap.texture >= 0);
  REQUIRE(m.specularColorMap.texture >= 0);
  CHECK_FALSE(scene.textures[size_t(m.specularMap.texture)].srgb);
  CHECK(scene.textures[size_t(m.specularColorMap.texture)].srgb);
  CHECK(m.specularColorMap.uvTransform[0] == glm::vec2(2.0f, 0.0f));
  CHECK(warnings.text().empty());  // both extensions and their maps are read
}

TEST_CASE("gltf materials: an index of refraction between 0 and 1 is refused, naming the field") {
  const TempDir dir;
  GltfBuilder builder;
  const int material = builder.addMaterial({{"extensions", {{"KHR_materials_ior", {{"ior", 0.5}}}}}});
  QuadSpec withMaterial;
  withMaterial.material = material;
  builder.addRootNode({{"mesh", pbr::test::addQuad(builder, withMaterial)}});
  pbr::Scene scene;
  CHECK_THROWS_WITH_AS(pbr::appendGltf(scene, builder.writeGltf(dir.path(), "ior")),
                       doctest::Contains("materials[0].extensions.KHR_materials_ior.ior: must be 0 or at least 1"),
                       pbr::SceneError);
}

TEST_CASE("materials: ior 1.5, specular 1 and a white specular colour are the core material's F0 0.04 and F90 1") {
  const pbr::Material core;
  // Exactly: 0.25 / 6.25 is the float nearest 0.04, as the core material's constant is.
  CHECK(pbr::dielectricSpecular(core) == glm::vec4(0.04f, 0.04f, 0.04f, 1.0f));
  CHECK_FALSE(pbr::hasDielectricSpecular(core));
  pbr::Material m;
  m.ior = 0.0f;  // the specular-glossiness conversion's: F0 1
  CHECK(pbr::dielectricSpecular(m) == glm::vec4(1.0f));
  m.ior = 1.5f;
  m.specular = 0.5f;
  m.specularColor = {100.0f, 1.0f, 0.0f};  // clamped to 1 before the strength scales it
  CHECK(pbr::dielectricSpecular(m) == glm::vec4(0.5f, 0.02f, 0.0f, 0.5f));
  CHECK(pbr::hasDielectricSpecular(m));
}

TEST_CASE("gltf materials: KHR_materials_pbrSpecularGlossiness becomes metal-rough by KHR_materials_specular's rule") {
  const TempDir dir;
  GltfBuilder builder;
  // A 2x1 specular-glossiness map: glossiness (alpha) 1 and 0.4; its colour is not drawn.
  pbr::ImageRgba8 map;
  map.width = 2;
  map.height = 1;
  map.pixels = {255, 0, 0, 255, 0, 255, 0, 102};
  const int glossTexture = builder.addPngTexture(dir.path(), "gloss.png", map);
  const int factorsOnly = builder.addMaterial(
      {{"extensions",
        {{"KHR_materials_pbrSpecularGlossiness",
          {{"diffuseFactor", {0.5, 0.25, 0.125, 0.75}},
           {"specularFactor", {0.2, 0.3, 0.4}},
           {"glossinessFactor", 0.6}}}}}});
  const int mapped = builder.addMaterial(
      {{"extensions",
        {{"KHR_materials_pbrSpecularGlossiness",
          {{"glossinessFactor", 0.5}, {"specularGlossinessTexture", {{"index", glossTexture}}}}}}}});
  builder.doc["extensionsUsed"] = {"KHR_materials_pbrSpecularGlossiness"};
  for (const int material : {factorsOnly, mapped}) {
    QuadSpec quad;
    quad.material = material;
    builder.addRootNode({{"mesh", pbr::test::addQuad(builder, quad)}});
  }
  pbr::Scene scene;
  const pbr::test::CapturedStderr warnings;
  pbr::appendGltf(scene, builder.writeGltf(dir.path(), "specgloss"));
  REQUIRE(scene.objects.size() == 2);
  const pbr::Material& a = scene.objects[0].material;
  CHECK(a.baseColor == glm::vec3(0.5f, 0.25f, 0.125f));
  CHECK(a.alpha == 0.75f);
  CHECK(a.metalness == 0.0f);
  CHECK(a.roughness == doctest::Approx(0.4f));
  // ior 0: F0 1 times the colour, so the dielectric's F0 is the specular factor itself.
  CHECK(pbr::dielectricSpecular(a) == glm::vec4(0.2f, 0.3f, 0.4f, 1.0f));
  const pbr::Material& b = scene.objects[1].material;
  REQUIRE(b.metallicRoughnessTexture >= 0);
  CHECK(b.roughness == 1.0f);
  const pbr::TextureData& roughness = scene.textures[size_t(b.metallicRoughnessTexture)];
  CHECK_FALSE(roughness.srgb);
  // Green: 1 - 0.5 x alpha, the roughness a metallic-roughness map holds; blue (metalness) 0.
  CHECK(int(roughness.rgba[1]) == 128);
  CHECK(int(roughness.rgba[5]) == 204);
  CHECK(int(roughness.rgba[2]) == 0);
  // The map decoded for this material's roughness alone is rewritten, not copied; its colour, sRGB, is the
  // specular colour map.
  REQUIRE(b.specularColorMap.texture >= 0);
  CHECK(scene.textures[size_t(b.specularColorMap.texture)].srgb);
  CHECK(scene.textures.size() == 2);
  CHECK(warnings.text().empty());
}

TEST_CASE("gltf materials: KHR_materials_clearcoat's factors and maps") {
  const TempDir dir;
  GltfBuilder builder;
  const int map = builder.addPngTexture(dir.path(), "map.png", {2, 2, std::vector<uint8_t>(16, 200)});
  const int material = builder.addMaterial(
      {{"extensions",
        {{"KHR_materials_clearcoat",
          {{"clearcoatFactor", 0.75},
           {"clearcoatRoughnessFactor", 0.25},
           {"clearcoatTexture", {{"index", map}, {"texCoord", 1}}},
           {"clearcoatNormalTexture", {{"index", map}, {"scale", 0.5}}}}}}}});
  builder.doc["extensionsUsed"] = {"KHR_materials_clearcoat"};
  QuadSpec quad;
  quad.material = material;
  builder.addRootNode({{"mesh", pbr::test::addQuad(builder, quad)}});
  pbr::Scene scene;
  const pbr::test::CapturedStderr warnings;
  pbr::appendGltf(scene, builder.writeGltf(dir.path(), "clearcoat"));
  REQUIRE(scene.objects.size() == 1);
  CHECK(scene.objects[0].material.clearcoat == 0.75f);
  CHECK(scene.objects[0].material.clearcoatRoughness == 0.25f);
  const pbr::Material& m = scene.objects[0].material;
  CHECK(m.clearcoatMap.texture >= 0);
  CHECK(m.clearcoatMap.texCoord == 1);
  CHECK(pbr::readsTexCoord1(m));
  CHECK(m.clearcoatNormalMap.texture >= 0);
  CHECK(m.clearcoatNormalScale == 0.5f);
  CHECK(m.clearcoatRoughnessMap.texture < 0);
  // The coat's map reads the second UV set, which this quad lacks: said, as for a core map.
  CHECK(warnings.text().find("its material reads TEXCOORD_1, which the primitive lacks") != std::string::npos);
  CHECK(pbr::materialExtensions(scene, false).clearcoat);
  CHECK_FALSE(pbr::materialExtensions(scene, true).clearcoat);
}

TEST_CASE("gltf materials: KHR_materials_transmission and _volume's factors and maps") {
  const TempDir dir;
  GltfBuilder builder;
  const int map = builder.addPngTexture(dir.path(), "map.png", {2, 2, std::vector<uint8_t>(16, 200)});
  const int glass = builder.addMaterial(
      {{"extensions",
        {{"KHR_materials_transmission", {{"transmissionFactor", 0.75}, {"transmissionTexture", {{"index", map}}}}},
         {"KHR_materials_volume",
          {{"thicknessFactor", 0.5},
           {"attenuationDistance", 2.0},
           {"attenuationColor", {1.0, 0.5, 0.25}},
           {"thicknessTexture", {{"index", map}}}}}}}});
  builder.doc["extensionsUsed"] = {"KHR_materials_transmission", "KHR_materials_volume"};
  QuadSpec quad;
  quad.material = glass;
  builder.addRootNode({{"mesh", pbr::test::addQuad(builder, quad)}});
  pbr::Scene scene;
  const pbr::test::CapturedStderr warnings;
  pbr::appendGltf(scene, builder.writeGltf(dir.path(), "glass"));
  REQUIRE(scene.objects.size() == 1);
  const pbr::Material& m = scene.objects[0].material;
  CHECK(m.transmission == 0.75f);
  CHECK(m.thickness == 0.5f);
  CHECK(m.attenuationDistance == 2.0f);
  CHECK(m.attenuationColor == glm::vec3(1.0f, 0.5f, 0.25f));
  CHECK(m.transmissionMap.texture >= 0);
  CHECK(m.thicknessMap.texture >= 0);
  CHECK(warnings.text().empty());
  // Forward-shaded: its extensions are the transparency pass's, not the G-buffer's.
  CHECK(pbr::isForwardShaded(m));
  // A negative thickness names the field.
  GltfBuilder bad;
  const int negative = bad.addMaterial({{"extensions", {{"KHR_materials_volume", {{"thicknessFactor", -1.0}}}}}});
  QuadSpec badQuad;
  badQuad.material = negative;
  bad.addRootNode({{"mesh", pbr::test::addQuad(bad, badQuad)}});
  pbr::Scene refused;
  CHECK_THROWS_WITH_AS(pbr::appendGltf(refused, bad.writeGltf(dir.path(), "bad")),
                       doctest::Contains("KHR_materials_volume.thicknessFactor: must be >= 0"), pbr::SceneError);
  // A map naming no texture names its field.
  GltfBuilder missing;
  const int noTexture = missing.addMaterial(
      {{"extensions", {{"KHR_materials_transmission", {{"transmissionTexture", {{"index", 3}}}}}}}});
  QuadSpec missingQuad;
  missingQuad.material = noTexture;
  missing.addRootNode({{"mesh", pbr::test::addQuad(missing, missingQuad)}});
  CHECK_THROWS_WITH_AS(
      pbr::appendGltf(refused, missing.writeGltf(dir.path(), "missing")),
      doctest::Contains("materials[0].extensions.KHR_materials_transmission.transmissionTexture.index"),
      pbr::SceneError);
}

TEST_CASE("gltf materials: KHR_materials_sheen's factors and maps") {
  const TempDir dir;
  GltfBuilder builder;
  const int map = builder.addPngTexture(dir.path(), "map.png", {2, 2, std::vector<uint8_t>(16, 200)});
  const int material = builder.addMaterial(
      {{"extensions",
        {{"KHR_materials_sheen",
          {{"sheenColorFactor", {1.0, 0.5, 0.25}},
           {"sheenRoughnessFactor", 0.75},
           {"sheenColorTexture", {{"index", map}}},
           {"sheenRoughnessTexture", {{"index", map}}}}}}}});
  builder.doc["extensionsUsed"] = {"KHR_materials_sheen"};
  QuadSpec quad;
  quad.material = material;
  builder.addRootNode({{"mesh", pbr::test::addQuad(builder, quad)}});
  pbr::Scene scene;
  const pbr::test::CapturedStderr warnings;
  pbr::appendGltf(scene, builder.writeGltf(dir.path(), "sheen"));
  REQUIRE(scene.objects.size() == 1);
  CHECK(scene.objects[0].material.sheenColor == glm::vec3(1.0f, 0.5f, 0.25f));
  CHECK(scene.objects[0].material.sheenRoughness == 0.75f);
  CHECK(scene.textures[size_t(scene.objects[0].material.sheenColorMap.texture)].srgb);
  CHECK_FALSE(scene.textures[size_t(scene.objects[0].material.sheenRoughnessMap.texture)].srgb);
  CHECK(warnings.text().empty());
  CHECK(pbr::materialExtensions(scene, false).sheen);
}
