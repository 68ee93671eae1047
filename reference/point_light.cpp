#include "reference/point_light.hpp"

#include <glm/geometric.hpp>

namespace pbr::reference {

LightIncidence incidence(const PointLight& light, const dvec3& P, const dvec3& N) {
  const dvec3 toLight = dvec3(light.position) - P;
  const double d = glm::length(toLight);
  const dvec3 L = d > 1e-12 ? toLight / d : N;
  return {L, glm::dot(N, L), attenuation(d, light.radius)};
}

dvec3 reflectedRadiance(const PointLight& light, const dvec3& P, const dvec3& N, const dvec3& V,
                        const ReferenceMaterial& m, const BrdfForms& forms) {
  const LightIncidence in = incidence(light, P, N);
  if (in.NoL <= 0.0 || in.attenuation <= 0.0) return dvec3(0.0);
  const double intensity = light.luminousPower / (4.0 * kPi);
  return evaluateBrdf(N, V, in.L, m, forms).sum() * dvec3(light.color) * (intensity * in.attenuation * in.NoL);
}

}  // namespace pbr::reference
