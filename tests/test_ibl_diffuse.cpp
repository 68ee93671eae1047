// Diffuse image-based lighting (ibl/irradiance_sh.hpp, shaders/ibl/ibl_sample.glsl): the 9-coefficient
// spherical-harmonic irradiance against a brute-force integration over the environment's cube texels, the white
// furnace, and the measurement behind choosing spherical harmonics over a convolved cube map (ibl/README.md).
#include <doctest/doctest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <vector>

#include <glm/vec4.hpp>

#include "core/gl/environment_maps.hpp"
#include "core/gl/shader_library.hpp"
#include "core/scene/assets.hpp"
#include "ibl/environment_cubemap.hpp"
#include "ibl/ibl_maps.hpp"
#include "ibl/irradiance_sh.hpp"
#include "reference/environment_integrals.hpp"
#include "reference/reference_brdf.hpp"
#include "tests/gl_test_context.hpp"
#include "tests/glsl_probe.hpp"
#include "tests/ibl_readback.hpp"

using pbr::test::GlslProbe;
using pbr::reference::kPi;

namespace {

std::vector<glm::vec4> asInput(const std::vector<glm::dvec3>& directions) {
  std::vector<glm::vec4> input;
  for (const glm::dvec3& d : directions) input.emplace_back(glm::vec3(d), 0.0f);
  return input;
}

// iblIrradiance(N) of the bound maps for each direction.
std::vector<glm::vec4> gpuIrradiance(const std::vector<glm::dvec3>& normals) {
  const GlslProbe probe("ibl irradiance", R"(
#include "ibl/ibl_sample.glsl"
vec4 probe(vec4 v) { return vec4(iblIrradiance(v.xyz), 0.0); }
)");
  return probe.run(asInput(normals));
}

struct ErrorStats {
  double meanRelative = 0.0;
  double maxRelative = 0.0;
  double maxOverMean = 0.0;  // largest error over the mean irradiance: relative errors in dark directions aside
};

// Errors of `estimate` against `reference`, per channel, over all directions.
ErrorStats errorStats(const std::vector<glm::vec4>& estimate, const std::vector<glm::dvec3>& reference) {
  ErrorStats s;
  glm::dvec3 mean(0.0);
  for (const glm::dvec3& e : reference) mean += e / static_cast<double>(reference.size());
  for (size_t i = 0; i < reference.size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      const double error = std::abs(estimate[i][c] - reference[i][c]);
      s.maxRelative = std::max(s.maxRelative, error / reference[i][c]);
      s.meanRelative += error / reference[i][c] / (3.0 * reference.size());
      s.maxOverMean = std::max(s.maxOverMean, error / mean[c]);
    }
  }
  return s;
}

double msSince(std::chrono::steady_clock::time_point start) {
  glFinish();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// The alternative to spherical harmonics, for the measurement only: an irradiance cube map convolved by brute
// force over every texel of one environment level.
class ConvolvedIrradiance {
 public:
  ConvolvedIrradiance()
      : program_(pbr::ShaderLibrary().computeFromSource("convolved irradiance", R"(#version 450 core
layout(local_size_x = 8, local_size_y = 8) in;
#include "ibl/cube_map.glsl"
layout(rgba16f, binding = 0) uniform readonly imageCube source;
layout(rgba16f, binding = 1) uniform writeonly imageCube irradiance;
void main() {
  ivec3 texel = ivec3(gl_GlobalInvocationID);
  int size = imageSize(irradiance).x, n = imageSize(source).x;
  if (texel.x >= size || texel.y >= size) return;
  vec3 N = cubeTexelDirection(texel, size);
  vec3 sum = vec3(0.0);
  for (int face = 0; face < 6; ++face) {
    for (int y = 0; y < n; ++y) {
      for (int x = 0; x < n; ++x) {
        ivec3 s = ivec3(x, y, face);
        float c = dot(N, cubeTexelDirection(s, n));
        if (c > 0.0) sum += imageLoad(source, s).rgb * (c * cubeTexelSolidAngle(s.xy, n));
      }
    }
  }
  imageStore(irradiance, texel, vec4(sum, 1.0));
}
)")) {}

  pbr::Cubemap run(const pbr::Cubemap& environment, int sourceLevel, int size) const {
    pbr::Cubemap out("test.convolved", GL_RGBA16F, size, 1);
    program_.use();
    glBindImageTexture(0, environment.id(), sourceLevel, GL_TRUE, 0, GL_READ_ONLY, GL_RGBA16F);
    glBindImageTexture(1, out.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA16F);
    const GLuint groups = (static_cast<GLuint>(size) + 7) / 8;
    glDispatchCompute(groups, groups, 6);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    glUseProgram(0);
    return out;
  }

 private:
  pbr::Program program_;
};

}  // namespace

TEST_CASE("ibl diffuse: a constant environment has irradiance pi L everywhere") {
  PBR_REQUIRE_GL();
  const pbr::ShaderLibrary shaders;
  const glm::vec3 radiance(0.5f, 1.0f, 2.0f);
  const pbr::IblMaps maps(shaders, pbr::Environment::uniform(radiance), pbr::test::smallIblSettings(16));
  pbr::bindEnvironmentMaps(maps.maps());
  const std::vector<glm::dvec3> normals = pbr::reference::fibonacciSphere(500);
  const std::vector<glm::vec4> e = gpuIrradiance(normals);
  for (size_t i = 0; i < normals.size(); ++i) {
    for (int c = 0; c < 3; ++c) REQUIRE(e[i][c] == doctest::Approx(kPi * radiance[c]).epsilon(2e-3));
  }
  // The coefficients themselves: the constant term only, L 4 pi Y00.
  const pbr::IblBlock block = pbr::test::readIblBlock(maps.irradiance());
  CHECK(block.sh[0].y == doctest::Approx(4.0 * kPi * 0.282095).epsilon(2e-3));
  for (int k = 1; k < 9; ++k) CHECK(std::abs(block.sh[k].y) < 1e-3);
}

TEST_CASE("ibl diffuse: white furnace, a white Lambert surface under a uniform environment of radiance 1 shades to 1") {
  PBR_REQUIRE_GL();
  const pbr::ShaderLibrary shaders;
  const pbr::IblMaps maps(shaders, pbr::Environment::uniform(glm::vec3(1.0f)), pbr::test::smallIblSettings(16));
  pbr::bindEnvironmentMaps(maps.maps());
  // Lambert with albedo 1 reflects E / pi; iblDiffuse is exactly that for the caller to multiply by its albedo.
  const GlslProbe probe("ibl white furnace", R"(
#include "ibl/ibl_sample.glsl"
vec4 probe(vec4 v) { return vec4(iblDiffuse(v.xyz) * vec3(1.0), 0.0); }
)");
  const std::vector<glm::dvec3> normals = pbr::reference::fibonacciSphere(1000);
  const std::vector<glm::vec4> shaded = probe.run(asInput(normals));
  for (const glm::vec4& l : shaded) {
    for (int c = 0; c < 3; ++c) REQUIRE(l[c] == doctest::Approx(1.0).epsilon(0.02));
  }
}

TEST_CASE("ibl diffuse: spherical-harmonic irradiance of the sky matches brute force over its cube texels") {
  PBR_REQUIRE_GL();
  const pbr::ShaderLibrary shaders;
  // A sun low over the horizon on a clear-sky gradient: the hardest case for 9 coefficients is light from one
  // small direction, whose irradiance has a crease where the sun sets below a surface's horizon.
  const pbr::Environment sky = pbr::Environment::sky(pbr::SkyParams{});
  constexpr int kSize = 32;
  const pbr::IblMaps maps(shaders, sky, pbr::test::smallIblSettings(kSize));
  pbr::bindEnvironmentMaps(maps.maps());
  const pbr::Cubemap cube = pbr::EnvironmentCubemapPass(shaders).run(sky, kSize);
  const pbr::reference::CubeTexels texels = pbr::test::cubeTexels(cube, 0);

  const std::vector<glm::dvec3> normals = pbr::reference::fibonacciSphere(400);
  std::vector<glm::dvec3> reference;
  for (const glm::dvec3& n : normals) reference.push_back(pbr::reference::bruteForceIrradiance(texels, n));
  const std::vector<glm::vec4> sh = gpuIrradiance(normals);

  // A rigorous bound: for light from one direction of irradiance E0 at normal incidence, bands 0-2 give
  // E0 (1/4 + c/2 + 5/32 (3c^2 - 1)) against E0 max(c, 0), c the cosine, at most 3/32 E0 apart (at c = 0).
  // Irradiance is linear in the radiance, so for any environment the error is at most 3/32 of the integral of L
  // over the sphere.
  const glm::dvec3 bound = pbr::reference::totalEnergy(texels) * (3.0 / 32.0);
  for (size_t i = 0; i < normals.size(); ++i) {
    for (int c = 0; c < 3; ++c) REQUIRE(std::abs(sh[i][c] - reference[i][c]) <= bound[c] * 1.001);
  }
  // What this sky gives (ibl/README.md), with a margin: errors peak where the sun sets below a normal's horizon.
  const ErrorStats s = errorStats(sh, reference);
  MESSAGE("sky, SH9 against brute force: mean relative error " << s.meanRelative << ", max " << s.maxRelative
                                                               << ", max over the mean irradiance " << s.maxOverMean);
  CHECK(s.meanRelative < 0.04);
  CHECK(s.maxOverMean < 0.12);
}

TEST_CASE("ibl diffuse: measurement, SH9 and a convolved cube map against brute force on the shipped environments") {
  PBR_REQUIRE_GL();
  const pbr::ShaderLibrary shaders;
  const pbr::EnvironmentCubemapPass environmentPass(shaders);
  const pbr::IrradianceShPass shPass(shaders);
  const ConvolvedIrradiance convolvedPass;
  const GlslProbe sampleCube("sample convolved", R"(
layout(binding = 0) uniform samplerCube irradianceMap;
vec4 probe(vec4 v) { return textureLod(irradianceMap, v.xyz, 0.0); }
)");
  constexpr int kFace = 128;
  constexpr int kConvolvedSize = 16;
  constexpr int kConvolvedSourceLevel = 2;  // 32^2 faces
  const std::vector<glm::dvec3> normals = pbr::reference::fibonacciSphere(1000);

  for (const std::string name : {"venice_sunset_1k", "pedestrian_overpass_1k"}) {
    CAPTURE(name);
    const pbr::Environment environment =
        pbr::Environment::fromHdrFile(pbr::assetPath("environments/" + name + ".hdr"));
    const pbr::Cubemap cube = environmentPass.run(environment, kFace);
    const pbr::reference::CubeTexels texels = pbr::test::cubeTexels(cube, 0);
    auto start = std::chrono::steady_clock::now();
    std::vector<glm::dvec3> reference;
    for (const glm::dvec3& n : normals) reference.push_back(pbr::reference::bruteForceIrradiance(texels, n));
    const double cpuMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();

    // Untimed first runs: llvmpipe compiles a shader's machine code at its first dispatch.
    shPass.run(cube);
    convolvedPass.run(cube, kConvolvedSourceLevel, kConvolvedSize);
    glFinish();
    start = std::chrono::steady_clock::now();
    const pbr::Buffer sh = shPass.run(cube);
    const double shMs = msSince(start);
    sh.bindBase(GL_UNIFORM_BUFFER, pbr::kIblUbo.index);
    const ErrorStats shError = errorStats(gpuIrradiance(normals), reference);

    start = std::chrono::steady_clock::now();
    const pbr::Cubemap convolved = convolvedPass.run(cube, kConvolvedSourceLevel, kConvolvedSize);
    const double convolvedMs = msSince(start);
    glBindTextureUnit(0, convolved.id());
    glBindSampler(0, 0);
    glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    const ErrorStats convolvedError = errorStats(sampleCube.run(asInput(normals)), reference);

    MESSAGE(name << " (" << kFace << "^2 faces, " << normals.size() << " normals; CPU brute force " << cpuMs
                 << " ms)\n  SH9:            " << shMs << " ms, mean relative error " << shError.meanRelative
                 << ", max " << shError.maxRelative << ", max over mean " << shError.maxOverMean
                 << "\n  convolved " << kConvolvedSize << "^2 from " << cube.faceSize(kConvolvedSourceLevel)
                 << "^2: " << convolvedMs << " ms, mean relative error " << convolvedError.meanRelative << ", max "
                 << convolvedError.maxRelative << ", max over mean " << convolvedError.maxOverMean);
    CHECK(shError.meanRelative < 0.01);
    CHECK(shError.maxRelative < 0.05);
  }
}
