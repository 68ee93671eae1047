#include "reference/point_light.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace pbr::reference {

LightIncidence incidence(const PointLight& light, const dvec3& P, const dvec3& N) {
  const dvec3 toLight = dvec3(light.position) - P;
  const double d = glm::length(toLight);
  const dvec3 L = d > 1e-12 ? toLight / d : N;
  double weight = attenuation(d, light.radius);
  if (light.spot) {
    // KHR_lights_punctual's smooth cone falloff, in double from the cone's angles.
    const double cosOuter = std::cos(double(light.spot->outerAngle));
    const double scale = 1.0 / std::max(1e-3, std::cos(double(light.spot->innerAngle)) - cosOuter);
    const double x = std::clamp((glm::dot(dvec3(light.spot->direction), -L) - cosOuter) * scale, 0.0, 1.0);
    weight *= x * x;
  }
  return {L, glm::dot(N, L), weight};
}

dvec3 reflectedRadiance(const PointLight& light, const dvec3& P, const dvec3& N, const dvec3& V,
                        const ReferenceMaterial& m, const BrdfForms& forms) {
  const LightIncidence in = incidence(light, P, N);
  if (in.attenuation <= 0.0) return dvec3(0.0);
  const double intensity = light.luminousPower / (4.0 * kPi);
  if (in.NoL < 0.0) {
    return transmissionLobe(N, V, in.L, m, forms) * dvec3(light.color) * (intensity * in.attenuation * -in.NoL);
  }
  if (in.NoL == 0.0) return dvec3(0.0);
  return evaluateBrdf(N, V, in.L, m, forms).sum() * dvec3(light.color) * (intensity * in.attenuation * in.NoL);
}

}  // namespace pbr::reference
