#include "reference/directional_albedo.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace pbr::reference {

namespace {
constexpr double kPi = 3.14159265358979323846;
}

dvec3 directionalAlbedo(const ReferenceMaterial& m, double NoV, const BrdfForms& forms, int samples) {
  const dvec3 N(0, 0, 1);
  const double cv = std::clamp(NoV, 1e-4, 1.0);
  const dvec3 V(std::sqrt(1.0 - cv * cv), 0.0, cv);
  const double r = std::max(m.roughness, kMinRoughness);
  const double alpha = r * r;
  dvec3 specular(0.0), diffuse(0.0);
  for (int i = 0; i < samples; ++i) {
    for (int j = 0; j < samples; ++j) {
      const double u = (i + 0.5) / samples, phi = 2.0 * kPi * (j + 0.5) / samples;
      // GGX half vector: tan^2(theta_h) = alpha^2 u / (1 - u), so pdf(h) = D(h) n.h and pdf(l) = pdf(h) / (4 v.h).
      const double cosH = std::sqrt((1.0 - u) / (1.0 + (alpha * alpha - 1.0) * u));
      const double sinH = std::sqrt(std::max(0.0, 1.0 - cosH * cosH));
      const dvec3 H(sinH * std::cos(phi), sinH * std::sin(phi), cosH);
      const double VoH = glm::dot(V, H);
      const dvec3 L = 2.0 * VoH * H - V;
      if (L.z > 0.0 && VoH > 0.0) {
        const double pdf = ggxD(cosH, alpha) * cosH / (4.0 * VoH);
        specular += evaluateBrdf(N, V, L, m, forms).specular * (L.z / pdf);
      }
      // Cosine-weighted directions: pdf(l) = n.l / pi.
      const double sinL = std::sqrt(u);
      const dvec3 Ld(sinL * std::cos(phi), sinL * std::sin(phi), std::sqrt(1.0 - u));
      diffuse += evaluateBrdf(N, V, Ld, m, forms).diffuse * kPi;
    }
  }
  return (specular + diffuse) / (double(samples) * samples);
}

}  // namespace pbr::reference
