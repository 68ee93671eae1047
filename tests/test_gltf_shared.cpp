// A glTF file loaded more than once into one scene: its meshes, materials and textures are appended once, its
// objects and lights once per load.
#include <doctest/doctest.h>

#include <filesystem>
#include <string>

#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include "core/scene/assets.hpp"
#include "core/scene/gltf_loader.hpp"
#include "tests/cli_util.hpp"
#include "tests/gltf_builder.hpp"

namespace fs = std::filesystem;
using nlohmann::json;
using pbr::test::TempDir;

namespace {

glm::mat4 placed(const glm::vec3& at, float scale) {
  return glm::scale(glm::translate(glm::mat4(1.0f), at), glm::vec3(scale));
}

void checkNear(const glm::mat4& got, const glm::mat4& want) {
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) CHECK(got[c][r] == doctest::Approx(want[c][r]).epsilon(1e-5));
  }
}

void checkNear(const glm::vec3& got, const glm::vec3& want) {
  for (int i = 0; i < 3; ++i) CHECK(got[i] == doctest::Approx(want[i]).epsilon(1e-6));
}

}  // namespace

TEST_CASE("gltf shared: DamagedHelmet loaded twice appends its mesh and textures once, its object twice") {
  const fs::path file = fs::path(pbr::assetDir()) / "DamagedHelmet/glTF-Binary/DamagedHelmet.glb";
  if (!fs::is_regular_file(file)) {
    MESSAGE("skipped: " << file.string() << " is missing");
    return;
  }
  const glm::mat4 first = placed({-3.0f, -0.5f, -3.0f}, 0.5f), second = placed({3.0f, -0.5f, 3.0f}, 0.5f);
  pbr::Scene scene;
  const pbr::Bounds a = pbr::appendGltf(scene, file.string(), first);
  const size_t meshes = scene.meshes.size(), textures = scene.textures.size(), objects = scene.objects.size();
  REQUIRE(objects > 0);
  // Another name of the same file: the record is found by canonical path.
  const pbr::Bounds b = pbr::appendGltf(scene, (file.parent_path() / "." / file.filename()).string(), second);

  CHECK(scene.meshes.size() == meshes);
  CHECK(scene.textures.size() == textures);
  CHECK(scene.gltfFiles.size() == 1);
  REQUIRE(scene.objects.size() == 2 * objects);
  for (size_t i = 0; i < objects; ++i) {
    const pbr::SceneObject &one = scene.objects[i], &two = scene.objects[objects + i];
    CHECK(two.mesh == one.mesh);
    CHECK(two.material.baseColorTexture == one.material.baseColorTexture);
    CHECK(two.material.normalTexture == one.material.normalTexture);
    CHECK(two.material.emissiveTexture == one.material.emissiveTexture);
    // The node's own transform, placed by the second load's.
    checkNear(two.transform, second * glm::inverse(first) * one.transform);
  }
  // Both loads measure the bounds of what they placed: the same model, half size, 6 units apart in x and z.
  checkNear(b.min, a.min + glm::vec3(6.0f, 0.0f, 6.0f));
  checkNear(b.max, a.max + glm::vec3(6.0f, 0.0f, 6.0f));
  // The node turns the Z-forward mesh by 90 degrees about X: mesh z in [-0.901, 0.901] becomes world y.
  CHECK(b.min.y == doctest::Approx(-0.5 - 0.5 * 0.901).epsilon(1e-3));
  CHECK(b.max.y == doctest::Approx(-0.5 + 0.5 * 0.901).epsilon(1e-3));
}

TEST_CASE("gltf shared: each load adds the file's lights, and a load that fails leaves scene and record as they were") {
  const TempDir dir;
  pbr::test::GltfBuilder builder;
  pbr::test::QuadSpec quad;
  builder.addPngTexture(dir.path(), "grey.png", pbr::test::solidImage(4, 4, {128, 128, 128, 255}));
  quad.material = builder.addMaterial({{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}});
  builder.addRootNode({{"mesh", pbr::test::addQuad(builder, quad)}});
  builder.doc["extensionsUsed"] = {"KHR_lights_punctual"};
  builder.doc["extensions"]["KHR_lights_punctual"]["lights"] = {{{"type", "point"}, {"intensity", 10.0}}};
  builder.addRootNode({{"translation", {0, 3, 0}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
  const std::string file = builder.writeGltf(dir.path(), "lamp");
  const fs::path link = dir.path() / "link.gltf";
  fs::create_symlink(file, link);

  pbr::Scene scene;
  pbr::appendGltf(scene, file, placed({-2.0f, 0.0f, 0.0f}, 1.0f));
  pbr::appendGltf(scene, link.string(), placed({2.0f, 0.0f, 0.0f}, 2.0f));
  CHECK(scene.meshes.size() == 1);
  CHECK(scene.textures.size() == 1);
  CHECK(scene.objects.size() == 2);
  REQUIRE(scene.lights.size() == 2);
  CHECK(scene.lights[0].position == glm::vec3(-2.0f, 3.0f, 0.0f));
  CHECK(scene.lights[1].position == glm::vec3(2.0f, 6.0f, 0.0f));
  CHECK(scene.gltfFiles.size() == 1);

  // This load's transform is checked as a first load's would be: the quad (y in [-1, 1]) fits within the
  // coordinate limit, the light's node (y = 3) is placed beyond it, after the quad's object was added.
  const glm::mat4 tooFar = placed({0.0f, 0.998e12f, 0.0f}, 1e9f);
  const char* const tooFarMessage = "nodes[1].translation: with its parents' transforms, places the node at";
  CHECK_THROWS_WITH_AS(pbr::appendGltf(scene, file, tooFar), doctest::Contains(tooFarMessage), pbr::SceneError);
  CHECK(scene.objects.size() == 2);
  CHECK(scene.lights.size() == 2);

  // A file whose first load fails leaves no record: the mesh and texture it had appended are gone with it.
  const std::string other = builder.writeGltf(dir.path(), "other");
  CHECK_THROWS_WITH_AS(pbr::appendGltf(scene, other, tooFar), doctest::Contains(tooFarMessage), pbr::SceneError);
  CHECK(scene.meshes.size() == 1);
  CHECK(scene.textures.size() == 1);
  CHECK(scene.objects.size() == 2);
  CHECK(scene.lights.size() == 2);
  CHECK(scene.gltfFiles.size() == 1);
  pbr::appendGltf(scene, other);
  CHECK(scene.meshes.size() == 2);
  CHECK(scene.textures.size() == 2);
  CHECK(scene.objects.back().mesh == 1);
  CHECK(scene.objects.back().material.baseColorTexture == 1);
  CHECK(scene.gltfFiles.size() == 2);
}
