// GPU unit tests of the post-processing and encoding GLSL (shaders/post/aces.glsl, post/srgb.glsl,
// common/octahedral.glsl) against references written from the published formulas.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <glm/vector_relational.hpp>

#include "reference/display_transform.hpp"
#include "tests/gl_test_context.hpp"
#include "tests/glsl_probe.hpp"

using pbr::test::GlslProbe;

namespace {

constexpr double kPi = 3.14159265358979323846;

double relativeError(double actual, double expected) { return std::abs(actual - expected) / std::abs(expected); }

double angleDegrees(const glm::dvec3& a, const glm::dvec3& b) {
  // atan2 of sine and cosine stays accurate for the tiny angles measured here, unlike acos of a dot product.
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)) * 180.0 / kPi;
}

}  // namespace

TEST_CASE("glsl post: acesFitted is monotonic, maps 0 to 0 and matches Hill's published fit") {
  PBR_REQUIRE_GL();
  const GlslProbe probe("aces", R"(
#include "post/aces.glsl"
vec4 probe(vec4 v) { return vec4(acesFitted(v.rgb), 0.0); }
)");
  constexpr int kRamp = 1024;
  std::vector<glm::vec4> input = {glm::vec4(0.0f)};
  // Grey ramp, log spaced over 1e-4..100 (six decades of scene luminance).
  for (int i = 0; i < kRamp; ++i) {
    input.emplace_back(glm::vec3(static_cast<float>(std::pow(10.0, -4.0 + 6.0 * i / (kRamp - 1)))), 0.0f);
  }
  const size_t coloured = input.size();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> exponent(-3.0, 2.0);
  for (int i = 0; i < 512; ++i) {
    glm::vec4 c(0.0f);
    for (int ch = 0; ch < 3; ++ch) c[ch] = static_cast<float>(std::pow(10.0, exponent(rng)));
    input.push_back(c);
  }
  // Saturated primaries and out-of-range HDR push the output matrix below 0 and the curve above 1.
  for (const glm::vec3& c : {glm::vec3(10, 0, 0), glm::vec3(0, 10, 0), glm::vec3(0, 0, 10), glm::vec3(0.01f, 0, 5),
                             glm::vec3(1e4f), glm::vec3(65504, 0, 0)}) {
    input.emplace_back(c, 0.0f);
  }
  const std::vector<glm::vec4> out = probe.run(input);

  for (int ch = 0; ch < 3; ++ch) CHECK(out[0][ch] < 1e-3f);
  for (size_t i = 0; i < out.size(); ++i) {
    INFO("acesFitted(" << input[i].x << ", " << input[i].y << ", " << input[i].z << ") = (" << out[i].x << ", "
                       << out[i].y << ", " << out[i].z << ")");
    CHECK(glm::all(glm::greaterThanEqual(glm::vec3(out[i]), glm::vec3(0.0f))));
    CHECK(glm::all(glm::lessThanEqual(glm::vec3(out[i]), glm::vec3(1.0f))));
    if (i > 0 && i < coloured) {
      CHECK(glm::all(glm::greaterThanEqual(glm::vec3(out[i]), glm::vec3(out[i - 1]))));
    }
    const glm::dvec3 expected = pbr::reference::acesHill(glm::dvec3(input[i]));
    INFO("reference (" << expected.x << ", " << expected.y << ", " << expected.z << ")");
    CHECK(glm::length(glm::dvec3(out[i]) - expected) < 1e-4);
  }
}

TEST_CASE("glsl post: srgbEncode hits the IEC 61966-2-1 values, is continuous at the knee and monotonic") {
  PBR_REQUIRE_GL();
  const GlslProbe probe("srgb", R"(
#include "post/srgb.glsl"
vec4 probe(vec4 v) { return vec4(srgbEncode(v.x), srgbEncode(v.xxx)); }
)");
  // The knee as the shader sees it: a float compare against the float literal 0.0031308.
  const float knee = 0.0031308f;
  const float belowKnee = std::nextafter(knee, 0.0f), aboveKnee = std::nextafter(knee, 1.0f);
  const std::vector<std::pair<float, double>> known = {
      {0.0f, 0.0}, {0.001f, 0.01292}, {knee, 0.0404499}, {0.18f, 0.461356}, {0.5f, 0.735357}, {1.0f, 1.0}};
  std::vector<glm::vec4> input = {glm::vec4(belowKnee), glm::vec4(aboveKnee)};
  for (const auto& k : known) input.emplace_back(k.first);
  // The linear segment must reach the knee: its end is where the two branches differ most clearly (5e-6 at
  // x = 0.0031), so a misplaced knee shows there rather than at the knee itself, where they agree to 3e-8.
  const size_t linear = input.size();
  constexpr int kLinear = 64;
  for (int i = 1; i <= kLinear; ++i) input.emplace_back(knee * static_cast<float>(i) / kLinear);
  const size_t ramp = input.size();
  constexpr int kRamp = 4096;
  for (int i = 0; i <= kRamp; ++i) input.emplace_back(static_cast<float>(i) / kRamp);
  const std::vector<glm::vec4> out = probe.run(input);

  for (size_t i = 0; i < out.size(); ++i) {
    CAPTURE(input[i].x);
    CHECK(glm::all(glm::equal(glm::vec3(out[i].y, out[i].z, out[i].w), glm::vec3(out[i].x))));
  }
  {
    INFO("linear branch just below the knee " << out[0].x << ", power branch just above " << out[1].x);
    CHECK(std::abs(out[1].x - out[0].x) < 1e-6);
  }
  for (size_t k = 0; k < known.size(); ++k) {
    CAPTURE(known[k].first);
    CAPTURE(out[2 + k].x);
    CHECK(std::abs(out[2 + k].x - known[k].second) < 1e-5);
  }
  for (size_t i = linear; i < ramp; ++i) {
    CAPTURE(input[i].x);
    CAPTURE(out[i].x);
    CHECK(relativeError(out[i].x, 12.92 * input[i].x) < 2e-7);
  }
  for (size_t i = ramp + 1; i < out.size(); ++i) {
    CAPTURE(input[i].x);
    CHECK(out[i].x > out[i - 1].x);
  }
}

TEST_CASE("glsl common: octahedral normals survive encode, RG16 quantisation and decode") {
  PBR_REQUIRE_GL();
  const GlslProbe probe("octahedral", R"(
#include "common/octahedral.glsl"
// v.w = 1 rounds the code to 16-bit UNORM as the G-buffer's GL_RG16 target does (GL 4.5, section 2.3.5.2).
vec4 probe(vec4 v) {
  vec2 e = octEncode(v.xyz);
  if (v.w > 0.5) e = round(e * 65535.0) / 65535.0;
  return vec4(octDecode(e), 0.0);
}
)");
  std::vector<glm::dvec3> dirs = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (int sx : {-1, 1})
    for (int sy : {-1, 1})
      for (int sz : {-1, 1}) dirs.emplace_back(sx, sy, sz);
  // Fibonacci sphere: near-uniform coverage without clustering at the poles.
  constexpr int kFibonacci = 10000;
  const double golden = kPi * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < kFibonacci; ++i) {
    const double z = 1.0 - 2.0 * (i + 0.5) / kFibonacci, r = std::sqrt(1.0 - z * z);
    dirs.emplace_back(r * std::cos(golden * i), r * std::sin(golden * i), z);
  }
  // The z = 0 boundary, where the encoding folds the lower hemisphere onto the square's corners.
  for (double z : {0.0, 1e-7, -1e-7, 1e-4, -1e-4}) {
    for (int i = 0; i < 360; ++i) dirs.emplace_back(std::cos(i * kPi / 180.0), std::sin(i * kPi / 180.0), z);
  }

  std::vector<glm::vec4> input;
  for (float quantise : {0.0f, 1.0f})
    for (const glm::dvec3& d : dirs) input.emplace_back(glm::vec3(glm::normalize(d)), quantise);
  const std::vector<glm::vec4> out = probe.run(input);

  double worst[2] = {0.0, 0.0};
  for (size_t i = 0; i < input.size(); ++i) {
    const double error = angleDegrees(glm::normalize(glm::dvec3(glm::vec3(input[i]))), glm::dvec3(glm::vec3(out[i])));
    REQUIRE(std::isfinite(error));
    // The angle ignores length, but shading needs a unit normal.
    CHECK(std::abs(glm::length(glm::dvec3(glm::vec3(out[i]))) - 1.0) < 1e-6);
    double& w = worst[input[i].w > 0.5f ? 1 : 0];
    w = std::max(w, error);
  }
  // Float rounding only: about a dozen operations of half an ulp (6e-8) each, magnified at most 2x by the map,
  // stay under 2e-6 rad (1.2e-4 degrees).
  CHECK(worst[0] < 1.2e-4);
  // Rounding to 1/65535 moves each code by up to 1.5e-5 in [-1,1]^2; on the octahedron |x|+|y|+|z| = 1 that is
  // at most sqrt(6) * 1.5e-5, and projecting to the sphere magnifies it by up to sqrt(3) at the face centres:
  // 6.5e-5 rad, 0.0037 degrees. 0.01 leaves room for the float error above.
  CHECK(worst[1] < 0.01);
}
