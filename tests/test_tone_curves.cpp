// The display transform's tone curves (--tonemap; shaders/post/tone_curves.glsl) against their published formulas,
// evaluated here: the post pass's 8-bit output within one level of the formula's, sRGB-encoded, at black, mid-grey,
// 1, 16, 1e4 and a saturated colour; the CPU reference's display transform (reference/display_transform.*) equal to
// the same formulas; every curve monotone per channel along a ramp; PBR Neutral's pass-through below its
// compression start; the grey ramp staying grey; AgX's sigmoid through its stated points.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include <glm/common.hpp>
#include <glm/exponential.hpp>
#include <glm/vec3.hpp>

#include "reference/display_transform.hpp"
#include "renderer/display_image.hpp"
#include "tests/gl_test_context.hpp"

namespace {

using Curve = std::function<glm::dvec3(glm::dvec3)>;

glm::dvec3 clamp01(glm::dvec3 c) { return glm::clamp(c, 0.0, 1.0); }

// Hill's fit: the sRGB-to-RRT input matrix, the rational fit of the RRT + ODT, the ODT-to-sRGB output matrix
// (rows as Hill publishes them).
glm::dvec3 acesHill(glm::dvec3 c) {
  const double in[3][3] = {
      {0.59719, 0.35458, 0.04823}, {0.07600, 0.90834, 0.01566}, {0.02840, 0.13383, 0.83777}};
  const double out[3][3] = {
      {1.60475, -0.53108, -0.07367}, {-0.10208, 1.10813, -0.00605}, {-0.00327, -0.07276, 1.07602}};
  glm::dvec3 v;
  for (int r = 0; r < 3; ++r) v[r] = in[r][0] * c.x + in[r][1] * c.y + in[r][2] * c.z;
  for (int i = 0; i < 3; ++i) {
    v[i] = (v[i] * (v[i] + 0.0245786) - 0.000090537) / (v[i] * (0.983729 * v[i] + 0.4329510) + 0.238081);
  }
  glm::dvec3 o;
  for (int r = 0; r < 3; ++r) o[r] = out[r][0] * v.x + out[r][1] * v.y + out[r][2] * v.z;
  return clamp01(o);
}

glm::dvec3 acesNarkowicz(glm::dvec3 x) {
  x *= 0.6;
  return clamp01(x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14));
}

// Khronos PBR Neutral as its specification states it (F90 0.04, Ks 0.76, Kd 0.15).
glm::dvec3 khronosNeutral(glm::dvec3 c) {
  const double f90 = 0.04, ks = 0.8 - f90, kd = 0.15;
  const double x = std::min({c.x, c.y, c.z});
  const double f = x <= 2.0 * f90 ? x - x * x / (4.0 * f90) : f90;
  const double p = std::max({c.x - f, c.y - f, c.z - f});
  if (p <= ks) return clamp01(c - f);
  const double pn = 1.0 - (1.0 - ks) * (1.0 - ks) / (p + 1.0 - 2.0 * ks);
  const double g = 1.0 / (kd * (p - pn) + 1.0);
  return clamp01((c - f) * (pn / p) * g + glm::dvec3(pn) * (1.0 - g));
}

glm::dvec3 reinhard(glm::dvec3 x) { return clamp01(x * (1.0 + x / 16.0) / (1.0 + x)); }
glm::dvec3 exponential(glm::dvec3 x) { return clamp01(1.0 - glm::exp(-x)); }

// Sobotka's calculate_sigmoid (github.com/EaryChow/AgX_LUT_Gen, sigmoid.py) step by step, with Blender's AgX Base
// arguments: pivots (10 / 16.5, 0.18^(1/2.4)), slope 2.4, transition lengths 0, powers 1.5, limits (0,0) and (1,1).
double agxSigmoid(double x) {
  const double px = 10.0 / 16.5, py = std::pow(0.18, 1.0 / 2.4), slope = 2.4, power = 1.5;
  // With transition lengths 0 both transitions sit at the pivot, and the linear section is the pivot alone.
  const auto scale = [&](double limitX, double limitY, double transitionX, double transitionY) {
    const double a = std::pow(slope * (limitX - transitionX), -power);
    const double b = std::pow(slope * (limitX - transitionX) / (limitY - transitionY), power) - 1.0;
    return std::pow(a * b, -1.0 / power);
  };
  const auto exponentialCurve = [&](double in, double s) {
    const double t = slope * (in - px) / s;
    return s * t / std::pow(1.0 + std::pow(t, power), 1.0 / power) + py;
  };
  const double toe = -scale(1.0, 1.0, 1.0 - px, 1.0 - py);  // the toe's limits, mirrored as sigmoid.py does
  const double shoulder = scale(1.0, 1.0, px, py);
  if (x < px) return exponentialCurve(x, toe);
  if (x <= px) return py;
  return exponentialCurve(x, shoulder);
}

// Blender's AgX Base without its hue mix: linear sRGB to Rec.2020 (ITU-R BT.2087), the inset, log2 over
// [-10, +6.5] stops around 0.18, the sigmoid, the power 2.4, the outset, Rec.2020 to sRGB; the code value is the
// power 1/2.4 of that, returned as the linear value the sRGB encoding turns into it.
glm::dvec3 agx(glm::dvec3 c) {
  const double toRec2020[3][3] = {
      {0.6274039, 0.3292830, 0.0433131}, {0.0690973, 0.9195404, 0.0113623}, {0.0163914, 0.0880133, 0.8955953}};
  const double inset[3][3] = {{0.856627153315983, 0.0951212405381588, 0.0482516061458583},
                              {0.137318972929847, 0.761241990602591, 0.101439036467562},
                              {0.11189821299995, 0.0767994186031903, 0.811302368396859}};
  const double outset[3][3] = {{1.1271005818144368, -0.11060664309660323, -0.016493938717834573},
                               {-0.1413297634984383, 1.157823702216272, -0.016493938717834257},
                               {-0.14132976349843826, -0.11060664309660294, 1.2519364065950405}};
  const double toSrgb[3][3] = {
      {1.6604910, -0.5876411, -0.0728499}, {-0.1245505, 1.1328999, -0.0083494}, {-0.0181508, -0.1005789, 1.1187297}};
  const auto times = [](const double (&m)[3][3], glm::dvec3 v) {
    glm::dvec3 o;
    for (int r = 0; r < 3; ++r) o[r] = m[r][0] * v.x + m[r][1] * v.y + m[r][2] * v.z;
    return o;
  };
  glm::dvec3 v = times(inset, times(toRec2020, c));
  const double low = std::log2(0.18) - 10.0, high = std::log2(0.18) + 6.5;
  for (int i = 0; i < 3; ++i) {
    v[i] = std::pow(agxSigmoid(std::clamp((std::log2(std::max(v[i], 1e-10)) - low) / (high - low), 0.0, 1.0)), 2.4);
  }
  v = clamp01(times(toSrgb, times(outset, v)));
  for (int i = 0; i < 3; ++i) {
    const double code = std::pow(v[i], 1.0 / 2.4);
    v[i] = code <= 0.04045 ? code / 12.92 : std::pow((code + 0.055) / 1.055, 2.4);
  }
  return v;
}

// IEC 61966-2-1 sRGB encoding, to 8 bits.
int srgb8(double v) {
  const double e = v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
  return int(std::lround(std::clamp(e, 0.0, 1.0) * 255.0));
}

pbr::ImageRgba8 display(const std::vector<glm::vec3>& inputs, pbr::ToneCurve curve) {
  pbr::ImageRgbaF image{int(inputs.size()), 1, {}};
  for (const glm::vec3& v : inputs) image.pixels.insert(image.pixels.end(), {v.x, v.y, v.z, 1.0f});
  const pbr::ShaderLibrary shaders;
  return pbr::displayImage(shaders, image, 1.0f, curve);
}

}  // namespace

TEST_CASE("tone curves: each curve's display values follow its published formula and rise with the input") {
  PBR_REQUIRE_GL();
  const std::vector<std::pair<pbr::ToneCurve, Curve>> curves = {
      {pbr::ToneCurve::AcesHill, acesHill},     {pbr::ToneCurve::AcesNarkowicz, acesNarkowicz},
      {pbr::ToneCurve::KhronosNeutral, khronosNeutral}, {pbr::ToneCurve::AgX, agx}, {pbr::ToneCurve::Reinhard, reinhard},
      {pbr::ToneCurve::Exponential, exponential}, {pbr::ToneCurve::Linear, clamp01}};
  const std::vector<glm::vec3> inputs = {{0, 0, 0},  {0.18f, 0.18f, 0.18f}, {1, 1, 1},
                                         {16, 16, 16}, {1e4f, 1e4f, 1e4f},  {4.0f, 0.5f, 0.1f}};
  std::vector<glm::vec3> ramp;
  for (int i = 0; i < 256; ++i) ramp.push_back(glm::vec3(std::pow(2.0f, -8.0f + 16.0f * float(i) / 255.0f)));
  for (const auto& [curve, formula] : curves) {
    CAPTURE(pbr::toString(curve));
    const pbr::ImageRgba8 shown = display(inputs, curve);
    for (size_t i = 0; i < inputs.size(); ++i) {
      CAPTURE(i);
      const glm::dvec3 expected = formula(glm::dvec3(inputs[i]));
      for (int c = 0; c < 3; ++c) CHECK(std::abs(int(shown.pixels[i * 4 + size_t(c)]) - srgb8(expected[c])) <= 1);
      const glm::dvec3 cpu = pbr::reference::toneMap(curve, glm::dvec3(inputs[i]));
      for (int c = 0; c < 3; ++c) CHECK(cpu[c] == doctest::Approx(expected[c]).epsilon(1e-9));
    }
    // Monotone per channel, and a grey ramp stays grey.
    const pbr::ImageRgba8 rising = display(ramp, curve);
    for (size_t i = 1; i < ramp.size(); ++i) {
      for (size_t c = 0; c < 3; ++c) CHECK(rising.pixels[i * 4 + c] >= rising.pixels[(i - 1) * 4 + c]);
      CHECK(std::abs(int(rising.pixels[i * 4]) - int(rising.pixels[i * 4 + 2])) <= 1);
    }
  }
  // PBR Neutral passes through what lies below its compression start, less the Fresnel offset: 0.5 grey shows as
  // 0.46.
  const pbr::ImageRgba8 neutral = display({{0.5f, 0.5f, 0.5f}}, pbr::ToneCurve::KhronosNeutral);
  CHECK(int(neutral.pixels[0]) == srgb8(0.46));
}

TEST_CASE("tone curves: AgX's sigmoid runs from (0, 0) through its fulcrum with slope 2.4 to (1, 1)") {
  const double px = 10.0 / 16.5, py = std::pow(0.18, 1.0 / 2.4), h = 1e-6;
  for (const auto& sigmoid : {agxSigmoid, pbr::reference::agxSigmoid}) {
    CHECK(sigmoid(0.0) == doctest::Approx(0.0).epsilon(1e-12));
    CHECK(sigmoid(px) == doctest::Approx(py).epsilon(1e-12));
    CHECK(sigmoid(1.0) == doctest::Approx(1.0).epsilon(1e-12));
    CHECK((sigmoid(px + h) - sigmoid(px - h)) / (2.0 * h) == doctest::Approx(2.4).epsilon(1e-4));
  }
  // The two evaluations agree everywhere between.
  for (int i = 0; i <= 100; ++i) {
    CHECK(pbr::reference::agxSigmoid(i / 100.0) == doctest::Approx(agxSigmoid(i / 100.0)).epsilon(1e-12));
  }
}
