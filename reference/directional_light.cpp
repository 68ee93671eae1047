#include "reference/directional_light.hpp"

#include <glm/geometric.hpp>

namespace pbr::reference {

dvec3 towardsLight(const DirectionalLight& light) { return -glm::normalize(dvec3(light.direction)); }

dvec3 reflectedRadiance(const DirectionalLight& light, const dvec3& N, const dvec3& V, const ReferenceMaterial& m,
                        const BrdfForms& forms) {
  const dvec3 L = towardsLight(light);
  const double NoL = glm::dot(N, L);
  if (NoL < 0.0) return transmissionLobe(N, V, L, m, forms) * dvec3(light.color) * (double(light.illuminance) * -NoL);
  if (NoL == 0.0) return dvec3(0.0);
  return evaluateBrdf(N, V, L, m, forms).sum() * dvec3(light.color) * (double(light.illuminance) * NoL);
}

}  // namespace pbr::reference
