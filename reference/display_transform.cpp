#include "reference/display_transform.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <glm/common.hpp>
#include <glm/exponential.hpp>

namespace pbr::reference {

// IEC 61966-2-1, the sRGB transfer function and its inverse.
double srgbCodeToLinear(int k) { return srgbCodeToLinearValue(k / 255.0); }

double srgbCodeToLinearValue(double c) {
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

double srgbEncode(double linear) {
  return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

namespace {

using Matrix = double[3][3];  // row-major, as published: out[i] = sum_j M[i][j] in[j]

dvec3 apply(const Matrix& m, const dvec3& c) {
  return dvec3(m[0][0] * c.x + m[0][1] * c.y + m[0][2] * c.z, m[1][0] * c.x + m[1][1] * c.y + m[1][2] * c.z,
               m[2][0] * c.x + m[2][1] * c.y + m[2][2] * c.z);
}

dvec3 clamp01(const dvec3& c) { return glm::clamp(c, dvec3(0.0), dvec3(1.0)); }

// Narkowicz 2015, "ACES Filmic Tone Mapping Curve", on 0.6 x the input.
dvec3 acesNarkowicz(dvec3 x) {
  x *= 0.6;
  return clamp01(x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14));
}

// Khronos PBR Neutral (KhronosGroup/ToneMapping, PBR_Neutral/README.md): F90 0.04, Ks 0.8 - F90, Kd 0.15.
dvec3 khronosNeutral(const dvec3& c) {
  const double f90 = 0.04, ks = 0.8 - f90, kd = 0.15;
  const double x = std::min({c.x, c.y, c.z});
  const double f = x <= 2.0 * f90 ? x - x * x / (4.0 * f90) : f90;
  const dvec3 shifted = c - f;
  const double p = std::max({shifted.x, shifted.y, shifted.z});
  if (p <= ks) return clamp01(shifted);
  const double pn = 1.0 - (1.0 - ks) * (1.0 - ks) / (p + 1.0 - 2.0 * ks);
  const double g = 1.0 / (kd * (p - pn) + 1.0);
  return clamp01(shifted * (pn / p) * g + dvec3(pn) * (1.0 - g));
}

// Blender's AgX Base (github.com/EaryChow/AgX_LUT_Gen, AgXBaseRec2020.py, AgXBasesRGB.py) without the hue mix:
// the matrices and steps of shaders/post/tone_curves.glsl, whose comment gives the sources.
dvec3 agx(const dvec3& c) {
  static const Matrix kSrgbToRec2020 = {
      {0.6274039, 0.3292830, 0.0433131}, {0.0690973, 0.9195404, 0.0113623}, {0.0163914, 0.0880133, 0.8955953}};
  static const Matrix kRec2020ToSrgb = {
      {1.6604910, -0.5876411, -0.0728499}, {-0.1245505, 1.1328999, -0.0083494}, {-0.0181508, -0.1005789, 1.1187297}};
  static const Matrix kInset = {{0.856627153315983, 0.0951212405381588, 0.0482516061458583},
                                {0.137318972929847, 0.761241990602591, 0.101439036467562},
                                {0.11189821299995, 0.0767994186031903, 0.811302368396859}};
  static const Matrix kOutset = {{1.1271005818144368, -0.11060664309660323, -0.016493938717834573},
                                 {-0.1413297634984383, 1.157823702216272, -0.016493938717834257},
                                 {-0.14132976349843826, -0.11060664309660294, 1.2519364065950405}};
  const double minEv = -10.0 + std::log2(0.18), maxEv = 6.5 + std::log2(0.18);
  const dvec3 inset = apply(kInset, apply(kSrgbToRec2020, c));
  dvec3 formed;
  for (int i = 0; i < 3; ++i) {
    const double encoded = std::clamp((std::log2(std::max(inset[i], 1e-10)) - minEv) / (maxEv - minEv), 0.0, 1.0);
    formed[i] = std::pow(agxSigmoid(encoded), 2.4);
  }
  const dvec3 shown = clamp01(apply(kRec2020ToSrgb, apply(kOutset, formed)));
  dvec3 out;
  for (int i = 0; i < 3; ++i) out[i] = srgbCodeToLinearValue(std::pow(shown[i], 1.0 / 2.4));
  return out;
}

}  // namespace

// Hill's ACES.hlsl (github.com/TheRealMJP/BakingLab): input matrix, RRT + ODT rational fit, output matrix.
dvec3 acesHill(const dvec3& color) {
  static const Matrix kInput = {
      {0.59719, 0.35458, 0.04823}, {0.07600, 0.90834, 0.01566}, {0.02840, 0.13383, 0.83777}};
  static const Matrix kOutput = {
      {1.60475, -0.53108, -0.07367}, {-0.10208, 1.10813, -0.00605}, {-0.00327, -0.07276, 1.07602}};
  const dvec3 v = apply(kInput, color);
  const dvec3 a = v * (v + 0.0245786) - 0.000090537;
  const dvec3 b = v * (0.983729 * v + 0.4329510) + 0.238081;
  return clamp01(apply(kOutput, a / b));
}

// Sobotka's port of Jed Smith's tunable sigmoid (AgX_LUT_Gen, sigmoid.py) with no linear section: on each side of
// the fulcrum, y = pivot + k e(s |x - pivot| / k), e(t) = t / (1 + t^p)^(1/p), the side's scale k reaching the
// limit (0 or 1) at x = 0 or 1: k = ((s run)^-p ((s run / rise)^p - 1))^(-1/p).
double agxSigmoid(double x) {
  const double pivotX = 10.0 / 16.5, pivotY = std::pow(0.18, 1.0 / 2.4), slope = 2.4, power = 1.5;
  const double run = x < pivotX ? pivotX : 1.0 - pivotX, rise = x < pivotX ? pivotY : 1.0 - pivotY;
  const double k =
      std::pow(std::pow(slope * run, -power) * (std::pow(slope * run / rise, power) - 1.0), -1.0 / power);
  const double t = slope * std::abs(x - pivotX) / k;
  return pivotY + (x < pivotX ? -k : k) * t / std::pow(1.0 + std::pow(t, power), 1.0 / power);
}

dvec3 toneMap(ToneCurve curve, const dvec3& c) {
  switch (curve) {
    case ToneCurve::AcesHill: return acesHill(c);
    case ToneCurve::AcesNarkowicz: return acesNarkowicz(c);
    case ToneCurve::KhronosNeutral: return khronosNeutral(c);
    case ToneCurve::AgX: return agx(c);
    // Reinhard et al. 2002, eq. 4, white point 4.
    case ToneCurve::Reinhard: return clamp01(c * (1.0 + c / 16.0) / (1.0 + c));
    // The seeds' exponential exposure curve.
    case ToneCurve::Exponential: return clamp01(1.0 - glm::exp(-c));
    case ToneCurve::Linear: return clamp01(c);
  }
  throw std::logic_error("tone curve without a formula");
}

glm::ivec3 displayCode(const dvec3& radiance, double exposure, ToneCurve curve) {
  const dvec3 shown = toneMap(curve, radiance * exposure);
  glm::ivec3 code;
  for (int i = 0; i < 3; ++i) code[i] = int(std::lround(std::clamp(srgbEncode(shown[i]), 0.0, 1.0) * 255.0));
  return code;
}

}  // namespace pbr::reference
