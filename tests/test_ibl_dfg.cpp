// The split-sum DFG table (ibl/dfg_table.hpp, shaders/ibl/dfg.comp) read back from the GPU against a
// double-precision quadrature of the renderer's specular BRDF, and its lookup iblDfg (shaders/ibl/ibl_sample.glsl).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/gl/shader_library.hpp"
#include "ibl/dfg_table.hpp"
#include "ibl/ibl_maps.hpp"
#include "reference/split_sum_dfg.hpp"
#include "tests/gl_test_context.hpp"
#include "tests/glsl_probe.hpp"
#include "tests/ibl_readback.hpp"

using pbr::test::GlslProbe;

namespace {
constexpr int kSize = 64;
constexpr int kSamples = 512;
}  // namespace

TEST_CASE("ibl dfg: the GPU table matches a double-precision quadrature within 1e-2 on a grid of n.v and roughness") {
  PBR_REQUIRE_GL();
  const pbr::Texture table = pbr::DfgTablePass(pbr::ShaderLibrary()).run(kSize, kSamples);
  CHECK(table.format() == GL_RG16F);
  const std::vector<glm::vec2> texels = pbr::test::readDfgTable(table);
  double worst = 0.0;
  for (int x : {0, 4, 16, 32, 48, 63}) {
    for (int y : {0, 8, 24, 40, 63}) {
      const double NoV = std::max(x / (kSize - 1.0), 1e-4), roughness = y / (kSize - 1.0);
      const glm::dvec2 expected = pbr::reference::splitSumDfg(NoV, roughness);
      const glm::vec2 gpu = texels[static_cast<size_t>(y) * kSize + x];
      CAPTURE(NoV);
      CAPTURE(roughness);
      CHECK(std::abs(gpu.x - expected.x) < 1e-2);
      CHECK(std::abs(gpu.y - expected.y) < 1e-2);
      worst = std::max({worst, std::abs(gpu.x - expected.x), std::abs(gpu.y - expected.y)});
    }
  }
  MESSAGE("DFG " << kSize << "^2, " << kSamples << " samples: largest difference from the quadrature " << worst);
  // A mirror seen head-on reflects F0: A = 1, B = 0.
  const glm::vec2 mirror = texels[kSize - 1];
  CHECK(mirror.x == doctest::Approx(1.0).epsilon(1e-2));
  CHECK(mirror.y == doctest::Approx(0.0).epsilon(1e-2));
  // At roughness 1 (a = 1) seen head-on, D = 1 / pi and G2 = 2 n.l / (1 + n.l), so with F = 1 the albedo
  // A + B = integral of n.l / (2 pi (1 + n.l)) dl = 1 - ln 2: a closed form that checks the quadrature too.
  const glm::vec2 rough = texels[static_cast<size_t>(kSize) * kSize - 1];
  CHECK(rough.x + rough.y == doctest::Approx(1.0 - std::log(2.0)).epsilon(5e-3));
  const glm::dvec2 roughReference = pbr::reference::splitSumDfg(1.0, 1.0);
  CHECK(roughReference.x + roughReference.y == doctest::Approx(1.0 - std::log(2.0)).epsilon(1e-4));
}

TEST_CASE("ibl dfg: iblDfg reads the texels whose centres lie on the ends of both ranges, and blends between") {
  PBR_REQUIRE_GL();
  const pbr::ShaderLibrary shaders;
  pbr::IblSettings settings;
  settings.faceSize = 8;
  settings.specularLevels = 2;
  settings.specularSamples = 4;
  settings.dfgSize = 16;
  settings.dfgSamples = 64;
  const pbr::IblMaps maps(shaders, pbr::Environment::uniform(glm::vec3(1.0f)), settings);
  pbr::bindEnvironmentMaps(maps.maps());
  const std::vector<glm::vec2> texels = pbr::test::readDfgTable(maps.dfg());
  const GlslProbe probe("ibl dfg lookup", R"(
#include "ibl/ibl_sample.glsl"
vec4 probe(vec4 v) { return vec4(iblDfg(v.x, v.y), 0.0, 0.0); }
)");
  std::vector<glm::vec4> input;
  std::vector<glm::vec2> expected;
  const int n = settings.dfgSize;
  for (int y = 0; y < n; y += 5) {
    for (int x = 0; x < n; x += 3) {
      input.emplace_back(x / (n - 1.0f), y / (n - 1.0f), 0.0f, 0.0f);
      expected.push_back(texels[static_cast<size_t>(y) * n + x]);
      if (x + 1 < n) {
        // Halfway to the next texel: the mean of the two.
        input.emplace_back((x + 0.5f) / (n - 1.0f), y / (n - 1.0f), 0.0f, 0.0f);
        const size_t at = static_cast<size_t>(y) * n + x;
        expected.push_back(0.5f * (texels[at] + texels[at + 1]));
      }
    }
  }
  const std::vector<glm::vec4> looked = probe.run(input);
  for (size_t i = 0; i < input.size(); ++i) {
    CAPTURE(i);
    // Bilinear weights carry 8 fractional bits on llvmpipe, and RG16F about 3 decimal digits.
    CHECK(std::abs(looked[i].x - expected[i].x) < 2e-3);
    CHECK(std::abs(looked[i].y - expected[i].y) < 2e-3);
  }
}
