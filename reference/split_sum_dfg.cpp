#include "reference/split_sum_dfg.hpp"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "reference/reference_brdf.hpp"

namespace pbr::reference {

glm::dvec2 splitSumDfg(double NoV, double roughness) {
  const double a = alphaFromRoughness(roughness);
  const glm::dvec3 v(std::sqrt(1.0 - NoV * NoV), 0.0, NoV);
  // theta_h = a sinh(t s) puts nodes hundredths of `a` apart under a narrow peak and still reaches the horizon.
  constexpr int kTheta = 512, kPhi = 256;
  const double s = std::asinh(kPi / 2.0 / a);
  glm::dvec2 sum(0.0);
  for (int i = 0; i < kTheta; ++i) {
    const double t = (i + 0.5) / kTheta;
    const double theta = a * std::sinh(t * s);
    const double dTheta = a * s * std::cosh(t * s) / kTheta;
    const double cosT = std::cos(theta), sinT = std::sin(theta);
    const double d = ggxD(cosT, a);
    for (int j = 0; j < kPhi; ++j) {
      const double phi = 2.0 * kPi * (j + 0.5) / kPhi;
      const glm::dvec3 h(sinT * std::cos(phi), sinT * std::sin(phi), cosT);
      const double VoH = glm::dot(v, h);
      const double NoL = 2.0 * VoH * cosT - NoV;
      if (VoH <= 0.0 || NoL <= 0.0) continue;
      // dl = 4 (v.h) dh turns the integral over l into one over the half vector.
      const double w = d * smithVisibilityExact(NoV, NoL, a) * NoL * 4.0 * VoH * sinT * dTheta * (2.0 * kPi / kPhi);
      // Schlick's F = F0 (1 - Fc) + Fc with Fc = (1 - v.h)^5, Schlick's reflectance for F0 = 0.
      const double fc = fresnelSchlick(VoH, 0.0);
      sum += glm::dvec2(1.0 - fc, fc) * w;
    }
  }
  return sum;
}

}  // namespace pbr::reference
