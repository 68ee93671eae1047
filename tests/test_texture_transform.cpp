// KHR_texture_transform read from small files written here: the matrix each material map's UVs go through, checked
// against the specification's formula computed here, the texCoord it may override, and a malformed value refused
// with one line naming its path. The render of a transformed texture is in test_gltf_render.cpp.
#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <glm/mat3x3.hpp>

#include "core/scene/gltf_loader.hpp"
#include "tests/cli_util.hpp"
#include "tests/gltf_builder.hpp"

using nlohmann::json;
using pbr::test::CapturedStderr;
using pbr::test::GltfBuilder;
using pbr::test::TempDir;

namespace {

constexpr double kPi = 3.14159265358979323846;

// A quad of `material`, whose maps all use texture 0, in a file that requires KHR_texture_transform.
std::string materialFile(const TempDir& dir, const std::string& name, const json& material) {
  GltfBuilder b;
  b.addPngTexture(dir.path(), "white.png", pbr::test::solidImage(1, 1, {255, 255, 255, 255}));
  pbr::test::QuadSpec spec;
  spec.material = b.addMaterial(material);
  b.addRootNode({{"mesh", pbr::test::addQuad(b, spec)}});
  b.doc["extensionsUsed"] = {"KHR_texture_transform"};
  b.doc["extensionsRequired"] = {"KHR_texture_transform"};
  return b.writeGltf(dir.path(), name);
}

// A textureInfo of texture 0 with `transform` as its KHR_texture_transform.
json transformed(const json& transform) {
  return {{"index", 0}, {"extensions", {{"KHR_texture_transform", transform}}}};
}

pbr::Material loadMaterial(const std::string& path) {
  pbr::Scene scene;
  pbr::appendGltf(scene, path);
  REQUIRE(scene.objects.size() == 1);
  return scene.objects[0].material;
}

// The specification's T * R * S as 3x3 matrices, with R as glTF issue #1563 corrects its listing: a positive rotation
// turns the UVs counter-clockwise as drawn with v down the image, taking +u towards -v.
glm::dvec2 specTransform(glm::dvec2 uv, glm::dvec2 offset, double rotation, glm::dvec2 scale) {
  const double c = std::cos(rotation), s = std::sin(rotation);
  const glm::dmat3 t(1, 0, 0, 0, 1, 0, offset.x, offset.y, 1);  // column-major, as GLSL
  const glm::dmat3 r(c, -s, 0, s, c, 0, 0, 0, 1);
  const glm::dmat3 sc(scale.x, 0, 0, 0, scale.y, 0, 0, 0, 1);
  return glm::dvec2(t * r * sc * glm::dvec3(uv, 1.0));
}

void checkMaps(const glm::mat3x2& matrix, const std::vector<std::pair<glm::dvec2, glm::dvec2>>& uvToExpected) {
  for (const auto& [uv, expected] : uvToExpected) {
    const glm::vec2 got = matrix * glm::vec3(glm::vec2(uv), 1.0f);
    CAPTURE(uv.x);
    CAPTURE(uv.y);
    CHECK(got.x == doctest::Approx(expected.x).epsilon(1e-6));
    CHECK(got.y == doctest::Approx(expected.y).epsilon(1e-6));
  }
}

// The images of a few UV points under `transform`, from specTransform.
std::vector<std::pair<glm::dvec2, glm::dvec2>> specImages(glm::dvec2 offset, double rotation, glm::dvec2 scale) {
  std::vector<std::pair<glm::dvec2, glm::dvec2>> out;
  for (const glm::dvec2 uv : {glm::dvec2(0, 0), glm::dvec2(1, 0), glm::dvec2(0, 1), glm::dvec2(0.3, 0.7)}) {
    out.emplace_back(uv, specTransform(uv, offset, rotation, scale));
  }
  return out;
}

}  // namespace

TEST_CASE("texture transform: each map's KHR_texture_transform becomes its UV matrix, identity where it has none") {
  const TempDir dir;
  const json material = {
      {"pbrMetallicRoughness",
       {{"baseColorTexture", transformed({{"offset", {0.25, 0.5}}, {"rotation", kPi / 2}, {"scale", {2, 3}}})},
        {"metallicRoughnessTexture", transformed({{"offset", {0.1, -0.2}}})}}},
      {"normalTexture", transformed({{"rotation", 0.3}})},
      {"occlusionTexture", transformed({{"scale", {0.5, -4}}, {"rotation", -1.0}, {"offset", {3, 0}}})},
      {"emissiveTexture", transformed(json::object())}};
  const std::string path = materialFile(dir, "maps", material);
  const CapturedStderr captured;
  const pbr::Material m = loadMaterial(path);
  CHECK(captured.text().empty());  // required and used, and implemented: nothing to say

  // By hand: u' = 3 v + 0.25, v' = -2 u + 0.5.
  checkMaps(m.baseColorUvTransform, {{{0, 0}, {0.25, 0.5}}, {{1, 0}, {0.25, -1.5}}, {{0, 1}, {3.25, 0.5}}});
  checkMaps(m.baseColorUvTransform, specImages({0.25, 0.5}, kPi / 2, {2, 3}));
  checkMaps(m.metallicRoughnessUvTransform, specImages({0.1, -0.2}, 0.0, {1, 1}));
  checkMaps(m.normalUvTransform, specImages({0, 0}, 0.3, {1, 1}));
  checkMaps(m.occlusionUvTransform, specImages({3, 0}, -1.0, {0.5, -4}));
  CHECK(m.emissiveUvTransform == glm::mat3x2(1.0f));
  CHECK(m.emissiveTexture >= 0);
}

TEST_CASE("texture transform: its texCoord replaces the textureInfo's, and one past 1 is warned about") {
  const TempDir dir;
  // The fallback the specification suggests: set 1 without the extension, set 0 with it.
  const json fallback = {{"index", 0},
                         {"texCoord", 1},
                         {"extensions", {{"KHR_texture_transform", {{"texCoord", 0}, {"scale", {2, 2}}}}}}};
  const std::string path = materialFile(
      dir, "texcoord", {{"pbrMetallicRoughness", {{"baseColorTexture", fallback}}},
                        {"emissiveTexture", transformed({{"texCoord", 1}, {"offset", {0.5, 0}}})},
                        {"occlusionTexture", transformed({{"texCoord", 2}})}});
  const CapturedStderr captured;
  const pbr::Material m = loadMaterial(path);
  CHECK(captured.text() == path +
                               ": materials[0].occlusionTexture.extensions.KHR_texture_transform: texCoord 2 is not "
                               "drawn (TEXCOORD_0 and TEXCOORD_1 are), TEXCOORD_0 is used\n" + path +
                               ": meshes[0].primitives[0].attributes: its material reads TEXCOORD_1, which the "
                               "primitive lacks: TEXCOORD_0 is used\n");
  CHECK(m.baseColorTexCoord == 0);
  CHECK(m.emissiveTexCoord == 1);
  CHECK(m.occlusionTexCoord == 0);
  checkMaps(m.baseColorUvTransform, specImages({0, 0}, 0.0, {2, 2}));
  checkMaps(m.emissiveUvTransform, specImages({0.5, 0}, 0.0, {1, 1}));
}

TEST_CASE("texture transform: a malformed value is one line naming the file and its path") {
  const TempDir dir;
  const std::string base = "materials[0].pbrMetallicRoughness.baseColorTexture.extensions.KHR_texture_transform";
  const auto onBaseColor = [](const json& transform) {
    return json{{"pbrMetallicRoughness", {{"baseColorTexture", transformed(transform)}}}};
  };
  struct Case {
    json material;
    std::string field, what;
  };
  const std::vector<Case> cases = {
      {onBaseColor({{"scale", {1}}}), base + ".scale", "must be an array of 2 numbers (got [1])"},
      {onBaseColor({{"scale", {1, 1, 1}}}), base + ".scale", "must be an array of 2 numbers"},
      {onBaseColor({{"offset", 0.5}}), base + ".offset", "must be an array of 2 numbers"},
      {onBaseColor({{"offset", {0, "a"}}}), base + ".offset[1]", "must be a number (got \"a\")"},
      {onBaseColor({{"rotation", {1}}}), base + ".rotation", "must be a number"},
      {onBaseColor({{"scale", {1e39, 1}}}), base + ".scale[0]", "must be a finite number within float range"},
      {onBaseColor({{"offset", {0, 10000000000}}}), base + ".offset[1]", "an integer beyond 32 bits"},
      {onBaseColor({{"texCoord", 0.5}}), base + ".texCoord", "must be a non-negative integer"},
      {onBaseColor(5), base, "must be an object (got 5)"},
      // Every map's transform is checked, by its own path.
      {{{"normalTexture", transformed({{"rotation", "a quarter turn"}})}},
       "materials[0].normalTexture.extensions.KHR_texture_transform.rotation", "must be a number"},
  };
  for (size_t i = 0; i < cases.size(); ++i) {
    const Case& c = cases[i];
    CAPTURE(c.field);
    const std::string path = materialFile(dir, "bad" + std::to_string(i), c.material);
    pbr::Scene scene;
    try {
      pbr::appendGltf(scene, path);
      FAIL("loaded");
    } catch (const pbr::SceneError& e) {
      const std::string message = e.what();
      CAPTURE(message);
      CHECK(message.rfind(path + ": " + c.field + ": ", 0) == 0);
      CHECK(message.find(c.what) != std::string::npos);
      CHECK(message.find('\n') == std::string::npos);
    }
  }
}
