// The split-sum shading of the lighting pass's IBL API (shaders/ibl/ibl_sample.glsl: shadeIbl) in white
// furnaces, and IblMaps as a whole: settings, memory, binding and profiler timing.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include "core/scene/assets.hpp"
#include "core/gl/environment_maps.hpp"
#include "core/gl/profiler.hpp"
#include "core/gl/shader_library.hpp"
#include "ibl/ibl_maps.hpp"
#include "reference/environment_integrals.hpp"
#include "reference/reference_brdf.hpp"
#include "reference/split_sum_dfg.hpp"
#include "tests/gl_test_context.hpp"
#include "tests/glsl_probe.hpp"
#include "tests/ibl_readback.hpp"

using pbr::test::GlslProbe;

namespace {

pbr::IblSettings smallSettings() {
  pbr::IblSettings s;
  s.faceSize = 16;
  s.specularLevels = 5;
  s.specularSamples = 32;
  s.dfgSize = 32;
  s.dfgSamples = 256;
  return s;
}

// shadeIbl of the material given by BASE, METALNESS and OCCLUSION for input (octahedral N, view tilt from N in
// radians, roughness); returns the shaded radiance and n.v.
const char* const kShadeProbe = R"(
#include "common/octahedral.glsl"
#include "ibl/ggx_sampling.glsl"
#include "ibl/ibl_sample.glsl"
vec4 probe(vec4 v) {
  vec3 N = octDecode(v.xy);
  vec3 V = basisAround(N) * vec3(sin(v.z), 0.0, cos(v.z));
  return vec4(shadeIbl(N, V, vec3(BASE), v.w, METALNESS, OCCLUSION), dot(N, V));
}
)";

// 100 normals x view tilts from 0 to 89 degrees x roughness 0 to 1.
std::vector<glm::vec4> shadingGrid() {
  std::vector<glm::vec4> input;
  for (const glm::dvec3& n : pbr::reference::fibonacciSphere(100)) {
    // octEncode (common/octahedral.glsl) in double.
    const glm::dvec3 o = n / (std::abs(n.x) + std::abs(n.y) + std::abs(n.z));
    glm::dvec2 e(o.x, o.y);
    if (o.z < 0.0) {
      e = (1.0 - glm::abs(glm::dvec2(o.y, o.x))) * glm::dvec2(o.x >= 0.0 ? 1.0 : -1.0, o.y >= 0.0 ? 1.0 : -1.0);
    }
    e = e * 0.5 + 0.5;
    for (double tiltDeg : {0.0, 30.0, 60.0, 80.0, 89.0}) {
      for (double roughness : {0.0, 0.1, 0.25, 0.5, 0.75, 1.0}) {
        input.emplace_back(e.x, e.y, tiltDeg * pbr::reference::kPi / 180.0, roughness);
      }
    }
  }
  return input;
}

GlslProbe shadeProbe(const std::string& base, const std::string& metalness, const std::string& occlusion,
                     bool multipleScattering = false) {
  return GlslProbe("ibl shade", kShadeProbe,
                   {{"BASE", base},
                    {"METALNESS", metalness},
                    {"OCCLUSION", occlusion},
                    {"IBL_MULTIPLE_SCATTERING", multipleScattering ? "1" : "0"}});
}

}  // namespace

TEST_CASE("ibl shade: white furnace, a white dielectric under radiance 1 shades to 1 at every roughness and view") {
  PBR_REQUIRE_GL();
  const pbr::ShaderLibrary shaders;
  const pbr::IblMaps maps(shaders, pbr::Environment::uniform(glm::vec3(1.0f)), smallSettings());
  pbr::bindEnvironmentMaps(maps.maps());
  // The specular lobe reflects F0 A + B of the prefiltered radiance (1 at every level) and the diffuse lobe gets
  // the rest, (1 - F0 A - B) E / pi with E = pi: the sum is 1 for any table, so this checks the plumbing from the
  // maps to the split sum, which a lost pi or a wrong level would break.
  const std::vector<glm::vec4> input = shadingGrid();
  const std::vector<glm::vec4> shaded = shadeProbe("1.0", "0.0", "1.0").run(input);
  for (size_t i = 0; i < input.size(); ++i) {
    CAPTURE(input[i].z);
    CAPTURE(input[i].w);
    for (int c = 0; c < 3; ++c) REQUIRE(shaded[i][c] == doctest::Approx(1.0).epsilon(0.02));
  }
  // Occlusion scales all of it.
  const std::vector<glm::vec4> occluded = shadeProbe("1.0", "0.0", "0.25").run(input);
  for (size_t i = 0; i < input.size(); ++i) REQUIRE(occluded[i].x == doctest::Approx(0.25).epsilon(0.02));
}

TEST_CASE("ibl shade: a white metal reflects A + B of the furnace, and 1 with the energy compensation") {
  PBR_REQUIRE_GL();
  const pbr::ShaderLibrary shaders;
  const pbr::IblMaps maps(shaders, pbr::Environment::uniform(glm::vec3(1.0f)), smallSettings());
  pbr::bindEnvironmentMaps(maps.maps());
  const std::vector<glm::vec4> input = shadingGrid();
  const std::vector<glm::vec4> single = shadeProbe("1.0", "1.0", "1.0").run(input);
  const std::vector<glm::vec4> compensated = shadeProbe("1.0", "1.0", "1.0", true).run(input);
  // The single-scattering albedo of F0 = 1, from the double-precision quadrature at the probe's n.v.
  std::map<std::pair<float, float>, glm::dvec2> references;  // by (view tilt, roughness)
  double worstLoss = 0.0;
  for (size_t i = 0; i < input.size(); ++i) {
    const double NoV = std::cos(static_cast<double>(input[i].z));
    const auto key = std::make_pair(input[i].z, input[i].w);
    if (!references.count(key)) references[key] = pbr::reference::splitSumDfg(NoV, input[i].w);
    const glm::dvec2 dfg = references[key];
    CAPTURE(NoV);
    CAPTURE(input[i].w);
    // The table is 32^2 here: linear interpolation between its texels costs up to about 0.03, except in the
    // first column, n.v < 1/31, where smooth metals' albedo rises steeply to 1 (ibl/README.md, Limits).
    if (NoV > 0.04) CHECK(single[i].x == doctest::Approx(dfg.x + dfg.y).epsilon(0.03));
    CHECK(compensated[i].x == doctest::Approx(1.0).epsilon(0.02));
    worstLoss = std::max(worstLoss, 1.0 - single[i].x);
  }
  // Without compensation rough metals lose a visible share of the light (Kulla & Conty 2017).
  MESSAGE("white metal in the furnace, single scattering: largest loss " << worstLoss);
  CHECK(worstLoss > 0.3);
}

TEST_CASE("ibl maps: a shipped 1k environment at the default settings, timed as one profiler frame of four passes") {
  PBR_REQUIRE_GL();
  const pbr::ShaderLibrary shaders;
  const pbr::Environment venice =
      pbr::Environment::fromHdrFile(pbr::assetPath("environments/venice_sunset_1k.hdr"), 1.0f, 30.0f);
  pbr::Profiler profiler(pbr::chooseTimingMode("auto", pbr::test::glContext()->info().renderer));
  const pbr::IblSettings settings;
  const pbr::IblMaps maps(shaders, venice, settings, &profiler);

  const std::vector<pbr::FrameTiming> frames = profiler.takeResults(true);
  REQUIRE(frames.size() == 1);
  const std::vector<std::string> expected = {"ibl environment", "ibl irradiance", "ibl specular", "ibl dfg"};
  REQUIRE(frames[0].passes.size() == expected.size());
  std::string timings;
  for (size_t i = 0; i < expected.size(); ++i) {
    CHECK(frames[0].passes[i].name == expected[i]);
    CHECK(frames[0].passes[i].ms > 0.0);
    timings += " " + expected[i] + " " + std::to_string(frames[0].passes[i].ms) + " ms;";
  }
  MESSAGE(std::string(pbr::describe(profiler.mode()))
          << ", faces " << settings.faceSize << "^2, " << settings.specularLevels << " specular levels x "
          << settings.specularSamples << " samples, DFG " << settings.dfgSize << "^2 x " << settings.dfgSamples << ":"
          << timings << " total " << frames[0].gpuMs << " ms, " << maps.bytes() << " bytes");

  // 144 B of coefficients, 6 levels of 128^2 down to 4^2 RGBA16F faces, 64^2 RG16F.
  size_t specularTexels = 0;
  for (int size = 128; size >= 4; size /= 2) specularTexels += 6 * size * size;
  CHECK(maps.bytes() == 144 + specularTexels * 8 + 64 * 64 * 4);
  CHECK(maps.specular().levels() == 6);
  CHECK(maps.specular().faceSize(5) == 4);
  for (int level = 0; level < maps.specular().levels(); ++level) {
    for (const glm::vec4& texel : pbr::test::readCubemapLevel(maps.specular(), level)) {
      REQUIRE((std::isfinite(texel.x) && std::isfinite(texel.y) && std::isfinite(texel.z)));
      REQUIRE((texel.x >= 0.0f && texel.y >= 0.0f && texel.z >= 0.0f));
    }
  }

  // bindEnvironmentMaps puts the maps where ibl_sample.glsl looks for them.
  pbr::bindEnvironmentMaps(maps.maps());
  GLint bound = 0;
  glGetIntegeri_v(GL_UNIFORM_BUFFER_BINDING, pbr::kIblUbo.index, &bound);
  CHECK(static_cast<GLuint>(bound) == maps.irradiance().id());
  glActiveTexture(GL_TEXTURE0 + pbr::kIblSpecularUnit.index);
  glGetIntegerv(GL_TEXTURE_BINDING_CUBE_MAP, &bound);
  CHECK(static_cast<GLuint>(bound) == maps.specular().id());
  glActiveTexture(GL_TEXTURE0 + pbr::kIblDfgUnit.index);
  glGetIntegerv(GL_TEXTURE_BINDING_2D, &bound);
  CHECK(static_cast<GLuint>(bound) == maps.dfg().id());
  glActiveTexture(GL_TEXTURE0);
  CHECK(glIsEnabled(GL_TEXTURE_CUBE_MAP_SEAMLESS));
}

TEST_CASE("ibl maps: settings and environments out of range are refused before any GPU work") {
  PBR_REQUIRE_GL();
  const pbr::ShaderLibrary shaders;
  const pbr::Environment white = pbr::Environment::uniform(glm::vec3(1.0f));
  const auto refused = [&](void (*change)(pbr::IblSettings&), const char* what) {
    pbr::IblSettings s;
    change(s);
    CHECK_THROWS_WITH_AS(pbr::IblMaps(shaders, white, s), doctest::Contains(what), std::invalid_argument);
  };
  refused([](pbr::IblSettings& s) { s.faceSize = 0; }, "faceSize");
  refused([](pbr::IblSettings& s) { s.specularLevels = 9; }, "specularLevels must be in [1, 8]");
  refused([](pbr::IblSettings& s) { s.specularSamples = 0; }, "specularSamples");
  refused([](pbr::IblSettings& s) { s.specularSamples = 65536; }, "specularSamples");
  refused([](pbr::IblSettings& s) { s.dfgSize = 1; }, "dfgSize");
  refused([](pbr::IblSettings& s) { s.dfgSamples = 0; }, "dfgSamples");

  CHECK_THROWS_AS(pbr::Environment::uniform(glm::vec3(-1.0f)), std::invalid_argument);
  CHECK_THROWS_AS(pbr::Environment::sky(pbr::SkyParams{}, -1.0f), std::invalid_argument);
  pbr::SkyParams noSun;
  noSun.sunDirection = glm::vec3(0.0f);
  CHECK_THROWS_AS(pbr::Environment::sky(noSun), std::invalid_argument);
  CHECK_THROWS_AS(pbr::Environment::fromEquirect(pbr::ImageRgbaF{2, 2, {}}), std::invalid_argument);
  CHECK_THROWS_AS(pbr::Environment::uniform(glm::vec3(1.0f)).equirect(), std::logic_error);
}
