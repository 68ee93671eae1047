// Each shipped scenes/*.json loads to the same scene as the built-in of the same name (at default parameters).
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <set>
#include <string>

#include "core/builtin_scenes.hpp"
#include "core/scene_json.hpp"

namespace fs = std::filesystem;

namespace {

constexpr float kEps = 1e-5f;

bool near(float a, float b) { return std::abs(a - b) <= kEps; }

void checkNear(const glm::vec3& got, const glm::vec3& want) {
  for (int i = 0; i < 3; ++i) CHECK(near(got[i], want[i]));
}

void checkSameMaterial(const pbr::Material& got, const pbr::Material& want) {
  checkNear(got.baseColor, want.baseColor);
  CHECK(near(got.roughness, want.roughness));
  CHECK(near(got.metalness, want.metalness));
  checkNear(got.emissive, want.emissive);
  CHECK(got.alpha == want.alpha);
  CHECK(got.alphaMode == want.alphaMode);
  CHECK(got.doubleSided == want.doubleSided);
  CHECK(got.baseColorTexture == want.baseColorTexture);
  CHECK(got.metallicRoughnessTexture == want.metallicRoughnessTexture);
  CHECK(got.normalTexture == want.normalTexture);
  CHECK(got.occlusionTexture == want.occlusionTexture);
  CHECK(got.emissiveTexture == want.emissiveTexture);
}

void checkSameScene(const pbr::Scene& got, const pbr::Scene& want) {
  CHECK(got.name == want.name);
  checkNear(got.camera.position, want.camera.position);
  checkNear(got.camera.target, want.camera.target);
  checkNear(got.camera.up, want.camera.up);
  CHECK(near(got.camera.fovYDeg, want.camera.fovYDeg));
  CHECK(near(got.camera.nearPlane, want.camera.nearPlane));
  CHECK(near(got.camera.farPlane, want.camera.farPlane));
  CHECK(near(got.exposure, want.exposure));
  checkNear(got.ambient, want.ambient);

  REQUIRE(got.objects.size() == want.objects.size());
  for (size_t i = 0; i < got.objects.size(); ++i) {
    CAPTURE(i);
    const pbr::SceneObject &g = got.objects[i], &w = want.objects[i];
    CHECK(g.shape == w.shape);
    for (int col = 0; col < 4; ++col) {
      for (int row = 0; row < 4; ++row) CHECK(near(g.transform[col][row], w.transform[col][row]));
    }
    checkSameMaterial(g.material, w.material);
  }

  REQUIRE(got.textures.size() == want.textures.size());
  for (size_t i = 0; i < got.textures.size(); ++i) {
    const pbr::TextureData &g = got.textures[i], &w = want.textures[i];
    CHECK(g.width == w.width);
    CHECK(g.height == w.height);
    CHECK(g.rgba == w.rgba);
    CHECK(g.srgb == w.srgb);
    CHECK(g.wrapS == w.wrapS);
    CHECK(g.wrapT == w.wrapT);
    CHECK(g.minFilter == w.minFilter);
    CHECK(g.magFilter == w.magFilter);
  }

  REQUIRE(got.lights.size() == want.lights.size());
  for (size_t i = 0; i < got.lights.size(); ++i) {
    CAPTURE(i);
    const pbr::PointLight &g = got.lights[i], &w = want.lights[i];
    checkNear(g.position, w.position);
    checkNear(g.color, w.color);
    CHECK(near(g.radius, w.radius));
    CHECK(near(g.luminousPower, w.luminousPower));
  }
}

}  // namespace

TEST_CASE("scene files: every scenes/*.json equals its built-in twin") {
  const fs::path folder = fs::path(PBR_SOURCE_DIR) / "scenes";
  std::set<std::string> checked;
  for (const fs::directory_entry& e : fs::directory_iterator(folder)) {
    if (e.path().extension() != ".json") continue;
    const std::string name = e.path().stem().string();
    CAPTURE(name);
    REQUIRE(pbr::isBuiltinScene(name));
    checkSameScene(pbr::loadSceneFile(e.path().string()), pbr::makeBuiltinScene(name));
    checked.insert(name);
  }
  for (const char* name : {"default", "sphere-grid", "light-wall", "fresnel-floor", "stress"}) {
    CHECK_MESSAGE(checked.count(name) == 1, "no scenes/" << name << ".json");
  }
}
