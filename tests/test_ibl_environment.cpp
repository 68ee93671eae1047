// Environment input of the IBL module on the GPU (ibl/environment_cubemap.hpp, shaders/ibl/cube_map.glsl):
// cube-map conventions against the GL specification and the driver's sampler, the equirectangular mapping,
// rotation and intensity, and the energy of the procedural sky's sun.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include "core/gl/shader_library.hpp"
#include "ibl/environment_cubemap.hpp"
#include "reference/cube_map_geometry.hpp"
#include "reference/environment_integrals.hpp"
#include "reference/reference_brdf.hpp"
#include "tests/gl_test_context.hpp"
#include "tests/glsl_probe.hpp"
#include "tests/ibl_readback.hpp"

using pbr::test::GlslProbe;
using pbr::reference::kPi;

namespace {

const glm::dvec3 kAxes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};

// An equirectangular image whose colour is its direction d as 0.5 d + 0.5, laid out as Environment documents:
// rows from +Y down, the centre column towards -Z, the column at 3/4 of the width towards +X.
pbr::ImageRgbaF directionCodedEquirect(int width, int height) {
  pbr::ImageRgbaF image;
  image.width = width;
  image.height = height;
  for (int y = 0; y < height; ++y) {
    const double theta = kPi * (y + 0.5) / height;
    for (int x = 0; x < width; ++x) {
      const double u = (x + 0.5) / width;
      const double phi = 2.0 * kPi * (u - 0.5);  // 0 at -Z, pi/2 at +X
      const glm::dvec3 d(std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi));
      for (int c = 0; c < 3; ++c) image.pixels.push_back(static_cast<float>(0.5 * d[c] + 0.5));
      image.pixels.push_back(1.0f);
    }
  }
  return image;
}

glm::dvec3 decodeDirection(const glm::vec4& texel) { return glm::normalize(glm::dvec3(texel) * 2.0 - 1.0); }

glm::vec4 faceCentre(const std::vector<glm::vec4>& texels, int face, int size) {
  // Faces have an even size: average the four texels around the centre.
  glm::vec4 sum(0.0f);
  for (int y = size / 2 - 1; y <= size / 2; ++y) {
    for (int x = size / 2 - 1; x <= size / 2; ++x) sum += texels[(static_cast<size_t>(face) * size + y) * size + x];
  }
  return sum * 0.25f;
}

}  // namespace

TEST_CASE("ibl environment: cube texel directions follow GL table 8.19 and the driver's cube sampler agrees") {
  PBR_REQUIRE_GL();
  // GLSL texel -> direction, mapped back by the specification's direction -> (face, s, t).
  const GlslProbe directions("cube texel direction", R"(
#include "ibl/cube_map.glsl"
vec4 probe(vec4 v) { return vec4(cubeTexelDirection(ivec3(v.xyz), int(v.w)), 0.0); }
)");
  for (int size : {1, 4, 7}) {
    std::vector<glm::vec4> input;
    for (int face = 0; face < 6; ++face) {
      for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) input.emplace_back(x, y, face, size);
      }
    }
    const std::vector<glm::vec4> output = directions.run(input);
    for (size_t i = 0; i < input.size(); ++i) {
      const pbr::reference::CubeCoord c = pbr::reference::cubeCoord(glm::dvec3(output[i]));
      CAPTURE(size);
      CAPTURE(i);
      CHECK(c.face == static_cast<int>(input[i].z));
      CHECK(static_cast<int>(std::floor(c.st.x * size)) == static_cast<int>(input[i].x));
      CHECK(static_cast<int>(std::floor(c.st.y * size)) == static_cast<int>(input[i].y));
      CHECK(glm::length(glm::dvec3(output[i]) - pbr::reference::cubeTexelDirection(c.face, static_cast<int>(input[i].x),
                                                                               static_cast<int>(input[i].y), size)) <
            1e-6);
    }
  }

  // A cube map whose texels hold (face, x, y), sampled by the driver along the reference's directions.
  constexpr int kSize = 4;
  const pbr::Cubemap coded("test.coded", GL_RGBA32F, kSize, 1);
  for (int face = 0; face < 6; ++face) {
    std::vector<glm::vec4> texels;
    for (int y = 0; y < kSize; ++y) {
      for (int x = 0; x < kSize; ++x) texels.emplace_back(face, x, y, 1.0f);
    }
    glTextureSubImage3D(coded.id(), 0, 0, 0, face, kSize, kSize, 1, GL_RGBA, GL_FLOAT, texels.data());
  }
  const pbr::Sampler nearest("test.nearest", GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE, GL_NEAREST, GL_NEAREST);
  glBindTextureUnit(0, coded.id());
  glBindSampler(0, nearest.id());
  const GlslProbe sampler("cube sampler", R"(
layout(binding = 0) uniform samplerCube cube;
vec4 probe(vec4 v) { return textureLod(cube, v.xyz, 0.0); }
)");
  std::vector<glm::vec4> input;
  std::vector<glm::ivec3> expected;
  for (int face = 0; face < 6; ++face) {
    for (int y = 0; y < kSize; ++y) {
      for (int x = 0; x < kSize; ++x) {
        input.emplace_back(glm::vec3(pbr::reference::cubeTexelDirection(face, x, y, kSize)), 0.0f);
        expected.emplace_back(face, x, y);
      }
    }
  }
  const std::vector<glm::vec4> sampled = sampler.run(input);
  glBindSampler(0, 0);
  for (size_t i = 0; i < input.size(); ++i) {
    CAPTURE(i);
    CHECK(glm::ivec3(sampled[i]) == expected[i]);
  }
}

TEST_CASE("ibl environment: an equirectangular image coded by direction lands on the right faces and texels") {
  PBR_REQUIRE_GL();
  const pbr::ShaderLibrary shaders;
  const pbr::EnvironmentCubemapPass pass(shaders);
  constexpr int kSize = 16;
  const pbr::Cubemap cube = pass.run(pbr::Environment::fromEquirect(directionCodedEquirect(128, 64)), kSize);
  CHECK(cube.levels() == 5);
  const std::vector<glm::vec4> texels = pbr::test::readCubemapLevel(cube, 0);

  // Face centres: +X shows +X and so on; the colour code is exact there up to filtering.
  for (int face = 0; face < 6; ++face) {
    CAPTURE(face);
    CHECK(glm::dot(decodeDirection(faceCentre(texels, face, kSize)), kAxes[face]) > 0.995);
  }
  // Every texel shows its own direction, within a texel's width (filtering blurs the code).
  double worst = 1.0;
  for (int face = 0; face < 6; ++face) {
    for (int y = 0; y < kSize; ++y) {
      for (int x = 0; x < kSize; ++x) {
        const glm::dvec3 shown = decodeDirection(texels[(static_cast<size_t>(face) * kSize + y) * kSize + x]);
        worst = std::min(worst, glm::dot(shown, pbr::reference::cubeTexelDirection(face, x, y, kSize)));
      }
    }
  }
  CHECK(std::acos(worst) < 2.0 / kSize);

  // Turned by 90 degrees about +Y, what lay towards +Z lies towards +X, and +X's towards -Z; +Y stays.
  const pbr::Cubemap turned =
      pass.run(pbr::Environment::fromEquirect(directionCodedEquirect(128, 64), 1.0f, 90.0f), kSize);
  const std::vector<glm::vec4> t = pbr::test::readCubemapLevel(turned, 0);
  CHECK(glm::dot(decodeDirection(faceCentre(t, 0, kSize)), kAxes[4]) > 0.995);
  CHECK(glm::dot(decodeDirection(faceCentre(t, 5, kSize)), kAxes[0]) > 0.995);
  CHECK(glm::dot(decodeDirection(faceCentre(t, 2, kSize)), kAxes[2]) > 0.995);
}

TEST_CASE("ibl environment: intensity scales the radiance, a uniform environment fills every texel of every level") {
  PBR_REQUIRE_GL();
  const pbr::ShaderLibrary shaders;
  const pbr::EnvironmentCubemapPass pass(shaders);
  pbr::ImageRgbaF grey;
  grey.width = 8;
  grey.height = 4;
  grey.pixels.assign(8 * 4 * 4, 0.25f);
  const pbr::Cubemap scaled = pass.run(pbr::Environment::fromEquirect(grey, 3.0f), 8);
  for (const glm::vec4& texel : pbr::test::readCubemapLevel(scaled, 0)) REQUIRE(texel.x == 0.75f);

  const glm::vec3 radiance(0.5f, 1.0f, 2.0f);
  const pbr::Cubemap uniform = pass.run(pbr::Environment::uniform(radiance), 8);
  for (int level = 0; level < uniform.levels(); ++level) {
    CAPTURE(level);
    for (const glm::vec4& texel : pbr::test::readCubemapLevel(uniform, level)) REQUIRE(glm::vec3(texel) == radiance);
  }
}

TEST_CASE("ibl environment: the sky's sun keeps its energy, widened to a texel or not, down the mip chain") {
  PBR_REQUIRE_GL();
  const pbr::ShaderLibrary shaders;
  const pbr::EnvironmentCubemapPass pass(shaders);
  constexpr int kSize = 32;
  for (float radiusDeg : {0.27f, 5.0f}) {
    CAPTURE(radiusDeg);
    pbr::SkyParams sky;
    sky.zenith = sky.horizon = sky.ground = glm::vec3(0.0f);
    sky.sunDirection = glm::vec3(0.3f, 0.8f, -0.5f);
    sky.sunAngularRadiusDeg = radiusDeg;
    sky.sunRadiance = glm::vec3(1000.0f);
    const pbr::Cubemap cube = pass.run(pbr::Environment::sky(sky), kSize);
    const double energy = 1000.0 * 2.0 * kPi * (1.0 - std::cos(radiusDeg * kPi / 180.0));
    for (int level = 0; level < 3; ++level) {
      CAPTURE(level);
      const pbr::reference::CubeTexels texels = pbr::test::cubeTexels(cube, level);
      CHECK(pbr::reference::totalEnergy(texels).x == doctest::Approx(energy).epsilon(0.03));
      // The brightest texel looks at the sun and is no brighter than it.
      size_t brightest = 0;
      for (size_t i = 0; i < texels.radiance.size(); ++i) {
        if (texels.radiance[i].x > texels.radiance[brightest].x) brightest = i;
      }
      CHECK(texels.radiance[brightest].x <= 1000.0 * 1.001);
      const double texelAngle = 2.0 / texels.size;
      CHECK(std::acos(glm::dot(texels.direction[brightest], glm::normalize(glm::dvec3(sky.sunDirection)))) <
            texelAngle);
    }
  }
}
