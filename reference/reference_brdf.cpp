#include "reference/reference_brdf.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace pbr::reference {

namespace {
constexpr double kPi = 3.14159265358979323846;
}

// Walter et al. 2007, "Microfacet Models for Refraction through Rough Surfaces".
double ggxD(double NoH, double alpha) {
  const double a2 = alpha * alpha;
  const double d = NoH * NoH * (a2 - 1.0) + 1.0;
  return a2 / (kPi * d * d);
}

// Heitz 2014, "Understanding the Masking-Shadowing Function": G2 / (4 n.l n.v), height-correlated.
double smithVisibilityExact(double NoV, double NoL, double alpha) {
  const double a2 = alpha * alpha;
  const double lv = NoL * std::sqrt(NoV * NoV * (1.0 - a2) + a2);
  const double ll = NoV * std::sqrt(NoL * NoL * (1.0 - a2) + a2);
  return 0.5 / (lv + ll);
}

// Cook & Torrance 1982, "A Reflectance Model for Computer Graphics", unpolarised dielectric Fresnel.
double fresnelDielectric(double c, double eta) {
  const double g2 = eta * eta - 1.0 + c * c;
  if (g2 < 0.0) return 1.0;
  const double g = std::sqrt(g2);
  const double a = (g - c) / (g + c);
  const double b = (c * (g + c) - 1.0) / (c * (g - c) + 1.0);
  return 0.5 * a * a * (1.0 + b * b);
}

double iorFromF0(double f0) {
  const double s = std::sqrt(std::clamp(f0, 0.0, 0.999));
  return (1.0 + s) / (1.0 - s);
}

BrdfLobes evaluateBrdf(const dvec3& N, const dvec3& V, const dvec3& L, const ReferenceMaterial& m) {
  const dvec3 H = glm::normalize(V + L);
  const double NoV = std::max(glm::dot(N, V), 1e-4);
  const double NoL = std::max(glm::dot(N, L), 0.0);
  const double NoH = std::clamp(glm::dot(N, H), 0.0, 1.0);
  const double VoH = std::clamp(glm::dot(V, H), 0.0, 1.0);
  const double r = std::max(m.roughness, kMinRoughness);
  const double alpha = r * r;
  const double eta = iorFromF0(0.04);
  // Metals: Schlick from their base colour; dielectrics: exact Fresnel; blended by metalness like F0 is.
  auto fresnel = [&](double c) {
    const dvec3 metal = m.baseColor + (dvec3(1.0) - m.baseColor) * std::pow(1.0 - c, 5.0);
    return (1.0 - m.metalness) * dvec3(fresnelDielectric(c, eta)) + m.metalness * metal;
  };
  const dvec3 specular = ggxD(NoH, alpha) * smithVisibilityExact(NoV, NoL, alpha) * fresnel(VoH);
  const dvec3 diffuse = (dvec3(1.0) - fresnel(NoV)) * (1.0 - m.metalness) * m.baseColor / kPi;
  return {diffuse, specular};
}

double attenuation(double d, double radius) {
  if (!(radius > 0.0)) return 0.0;
  const double x = d / radius;
  const double window = std::clamp(1.0 - x * x * x * x, 0.0, 1.0);
  const double dc = std::max(d, 0.01);
  return std::min(window * window / (dc * dc), 1.0);
}

}  // namespace pbr::reference
