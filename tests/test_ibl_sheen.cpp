// KHR_materials_sheen under an environment (ibl/sheen_prefilter.hpp, shaders/ibl/prefilter_sheen.comp): the
// Charlie-prefiltered cube map against a double-precision sum over the environment's cube texels, read through
// the shader's own lookup (iblSheen), and made only for scenes with a sheen.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <glm/vec4.hpp>

#include "core/gl/environment_maps.hpp"
#include "core/gl/shader_library.hpp"
#include "ibl/environment_cubemap.hpp"
#include "ibl/ibl_maps.hpp"
#include "reference/environment_integrals.hpp"
#include "tests/gl_test_context.hpp"
#include "tests/glsl_probe.hpp"
#include "tests/ibl_readback.hpp"

namespace {

pbr::IblSettings sheenSettings(int faceSize) {
  pbr::IblSettings s = pbr::test::smallIblSettings(faceSize);
  s.sheen = true;  // with the default sheen settings
  return s;
}

}  // namespace

TEST_CASE("ibl sheen: the Charlie-prefiltered environment matches a brute-force sum over the cube's texels") {
  PBR_REQUIRE_GL();
  const pbr::ShaderLibrary shaders;
  // The sky's sun low over the horizon: the Charlie lobe leans towards grazing light, where the sun is.
  const pbr::Environment sky = pbr::Environment::sky(pbr::SkyParams{});
  constexpr int kSize = 32;
  const pbr::IblMaps maps(shaders, sky, sheenSettings(kSize));
  REQUIRE(maps.sheen() != nullptr);
  pbr::bindEnvironmentMaps(maps.maps());
  const pbr::Cubemap cube = pbr::EnvironmentCubemapPass(shaders).run(sky, kSize);
  const pbr::reference::CubeTexels texels = pbr::test::cubeTexels(cube, 0);
  // Each texel of the levels at roughness 0.2, 0.6 and 1 (levels 1, 3 and 5 of 6) against the sum at its direction;
  // the brightest texel's radiance scales the tolerance: the darker ones see the sun's lobe alone.
  for (const int level : {1, 3, 5}) {
    const double roughness = level / 5.0;
    const pbr::reference::CubeTexels prefiltered = pbr::test::cubeTexels(*maps.sheen(), level);
    std::vector<glm::dvec3> reference;
    double brightest = 0.0;
    for (const glm::dvec3& n : prefiltered.direction) {
      reference.push_back(pbr::reference::bruteForceSheen(texels, n, roughness));
      brightest = std::max(brightest, std::max({reference.back().x, reference.back().y, reference.back().z}));
    }
    double worst = 0.0;
    for (size_t i = 0; i < reference.size(); ++i) {
      for (int c = 0; c < 3; ++c) {
        worst = std::max(worst, std::abs(prefiltered.radiance[i][c] - reference[i][c]) /
                                    (0.05 * reference[i][c] + 0.01 * brightest));
      }
    }
    MESSAGE("level " << level << " (sheen roughness " << roughness << "): worst error " << worst
                     << " of the bound 5 % + 1 % of the brightest texel");
    CHECK(worst <= 1.0);
  }
  // The shader's lookup reads the level of the roughness: at roughness 1, the 1x1 faces' texels.
  const pbr::test::GlslProbe probe("ibl sheen", R"(
#define MATERIAL_SHEEN 1
#include "ibl/ibl_sample.glsl"
vec4 probe(vec4 v) { return vec4(iblSheen(v.xyz, v.w), 0.0); }
)");
  const pbr::reference::CubeTexels top = pbr::test::cubeTexels(*maps.sheen(), 5);
  std::vector<glm::vec4> input;
  for (const glm::dvec3& n : top.direction) input.emplace_back(glm::vec3(n), 1.0f);
  const std::vector<glm::vec4> read = probe.run(input);
  for (size_t i = 0; i < read.size(); ++i) {
    for (int c = 0; c < 3; ++c) CHECK(double(read[i][c]) == doctest::Approx(top.radiance[i][c]).epsilon(1e-3));
  }
}

TEST_CASE("ibl sheen: a uniform environment stays itself, and the cube is made only when a scene asks for it") {
  PBR_REQUIRE_GL();
  const pbr::ShaderLibrary shaders;
  const pbr::Environment uniform = pbr::Environment::uniform(glm::vec3(0.5f, 1.0f, 2.0f));
  const pbr::IblMaps maps(shaders, uniform, sheenSettings(16));
  REQUIRE(maps.sheen() != nullptr);
  for (int level = 0; level < maps.sheen()->levels(); ++level) {
    for (const glm::vec4& texel : pbr::test::readCubemapLevel(*maps.sheen(), level)) {
      CHECK(texel.x == doctest::Approx(0.5).epsilon(1e-3));
      CHECK(texel.y == doctest::Approx(1.0).epsilon(1e-3));
      CHECK(texel.z == doctest::Approx(2.0).epsilon(1e-3));
    }
  }
  pbr::IblSettings plain = sheenSettings(16);
  plain.sheen = false;
  const pbr::IblMaps without(shaders, uniform, plain);
  CHECK(without.sheen() == nullptr);
  CHECK(without.maps().sheenCube == 0u);
  CHECK(without.bytes() < maps.bytes());
}
