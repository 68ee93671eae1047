#include "tests/study_brdf.hpp"

#include <cmath>

#include <glm/geometric.hpp>

namespace pbr::test {

glm::dvec3 studyBrdf(const glm::dvec3& N, const glm::dvec3& V, const glm::dvec3& L, const glm::dvec3& baseColor,
                     double roughness, double metalness) {
  constexpr double kPi = 3.14159265358979323846;
  const glm::dvec3 H = glm::normalize(V + L);
  const double nh = glm::dot(N, H), nv = glm::dot(N, V), nl = glm::dot(N, L), vh = glm::dot(V, H);
  const double a = roughness * roughness, a2 = a * a;
  // GGX (Walter et al. 2007): D = a^2 / (pi ((n.h)^2 (a^2 - 1) + 1)^2).
  const double q = nh * nh * (a2 - 1.0) + 1.0;
  const double d = a2 / (kPi * q * q);
  // Hammon 2017: V = 0.5 / mix(2 n.l n.v, n.l + n.v, a).
  const double vis = 0.5 / ((1.0 - a) * (2.0 * nl * nv) + a * (nl + nv));
  // Schlick 1994 with F0 = mix(0.04, baseColor, metalness).
  const glm::dvec3 f0 = glm::dvec3(0.04) * (1.0 - metalness) + baseColor * metalness;
  const glm::dvec3 f = f0 + (glm::dvec3(1.0) - f0) * std::pow(1.0 - vh, 5.0);
  const glm::dvec3 diffuse = (glm::dvec3(1.0) - f) * (1.0 - metalness) * baseColor / kPi;
  return diffuse + d * vis * f;
}

}  // namespace pbr::test
