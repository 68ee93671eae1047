#include "reference/display_transform.hpp"

#include <cmath>

#include <glm/common.hpp>

namespace pbr::reference {

// IEC 61966-2-1, the sRGB transfer function and its inverse.
double srgbCodeToLinear(int k) {
  const double c = k / 255.0;
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

double srgbEncode(double linear) {
  return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

// Hill's ACES.hlsl (github.com/TheRealMJP/BakingLab): input matrix, RRT + ODT rational fit, output matrix.
dvec3 acesHill(const dvec3& color) {
  // Row-major, as published: out[i] = sum_j M[i][j] in[j].
  static const double kInput[3][3] = {
      {0.59719, 0.35458, 0.04823}, {0.07600, 0.90834, 0.01566}, {0.02840, 0.13383, 0.83777}};
  static const double kOutput[3][3] = {
      {1.60475, -0.53108, -0.07367}, {-0.10208, 1.10813, -0.00605}, {-0.00327, -0.07276, 1.07602}};
  const auto apply = [](const double (&m)[3][3], const dvec3& c) {
    return dvec3(m[0][0] * c.x + m[0][1] * c.y + m[0][2] * c.z, m[1][0] * c.x + m[1][1] * c.y + m[1][2] * c.z,
                 m[2][0] * c.x + m[2][1] * c.y + m[2][2] * c.z);
  };
  const dvec3 v = apply(kInput, color);
  const dvec3 a = v * (v + 0.0245786) - 0.000090537;
  const dvec3 b = v * (0.983729 * v + 0.4329510) + 0.238081;
  return glm::clamp(apply(kOutput, a / b), dvec3(0.0), dvec3(1.0));
}

}  // namespace pbr::reference
