#include "reference/blinn_phong.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "reference/point_light.hpp"

namespace pbr::reference {

namespace {

dvec3 diffuseColor(const ReferenceMaterial& m) { return (1.0 - m.metalness) * m.baseColor; }

// Blinn 1977, "Models of Light Reflection for Computer Synthesized Pictures": (n.h)^n.
// Karis 2012, "Spherical Gaussian approximation for Blinn-Phong, Phong and Fresnel": e^(n (n.h - 1)).
double lobeValue(double NoH, double shininess, BlinnPhongLobe lobe) {
  return lobe == BlinnPhongLobe::SphericalGaussian ? std::exp(shininess * (NoH - 1.0)) : std::pow(NoH, shininess);
}

}  // namespace

dvec3 blinnPhongAmbient(const ReferenceMaterial& m) { return 0.02 * diffuseColor(m); }

dvec3 blinnPhongLight(const PointLight& light, const dvec3& P, const dvec3& N, const dvec3& V,
                      const ReferenceMaterial& m, BlinnPhongLobe lobe) {
  const LightIncidence in = incidence(light, P, N);
  if (in.NoL <= 0.0) return dvec3(0.0);
  const double alpha = alphaFromRoughness(m.roughness);
  const double shininess = 2.0 / (alpha * alpha) - 2.0;
  const double NoH = std::max(glm::dot(N, glm::normalize(V + in.L)), 0.0);
  // The core material's F0: the specular extensions are terms of the PBR model, which Blinn-Phong frames ignore.
  const dvec3 f0 = (1.0 - m.metalness) * dvec3(0.04) + m.metalness * m.baseColor;
  return (diffuseColor(m) * in.NoL + f0 * lobeValue(NoH, shininess, lobe)) * dvec3(light.color) * in.attenuation;
}

}  // namespace pbr::reference
