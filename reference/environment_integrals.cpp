#include "reference/environment_integrals.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "reference/cube_map_geometry.hpp"
#include "reference/reference_brdf.hpp"

namespace pbr::reference {

CubeTexels cubeTexels(const std::vector<glm::vec4>& texels, int size) {
  CubeTexels out;
  out.size = size;
  for (int face = 0; face < 6; ++face) {
    for (int y = 0; y < size; ++y) {
      for (int x = 0; x < size; ++x) {
        out.radiance.emplace_back(texels[(static_cast<size_t>(face) * size + y) * size + x]);
        out.direction.push_back(cubeTexelDirection(face, x, y, size));
        out.solidAngle.push_back(cubeTexelSolidAngle(x, y, size));
      }
    }
  }
  return out;
}

glm::dvec3 totalEnergy(const CubeTexels& texels) {
  glm::dvec3 sum(0.0);
  for (size_t i = 0; i < texels.radiance.size(); ++i) sum += texels.radiance[i] * texels.solidAngle[i];
  return sum;
}

glm::dvec3 bruteForceIrradiance(const CubeTexels& texels, const glm::dvec3& n) {
  glm::dvec3 sum(0.0);
  for (size_t i = 0; i < texels.radiance.size(); ++i) {
    const double cosine = glm::dot(n, texels.direction[i]);
    if (cosine > 0.0) sum += texels.radiance[i] * (cosine * texels.solidAngle[i]);
  }
  return sum;
}

std::vector<glm::dvec3> fibonacciSphere(int n) {
  std::vector<glm::dvec3> points;
  const double golden = kPi * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < n; ++i) {
    const double y = 1.0 - (2.0 * i + 1.0) / n;
    const double r = std::sqrt(std::max(0.0, 1.0 - y * y));
    points.emplace_back(r * std::cos(golden * i), y, r * std::sin(golden * i));
  }
  return points;
}

glm::dvec3 bruteForceSheen(const CubeTexels& texels, const glm::dvec3& n, double sheenRoughness) {
  glm::dvec3 sum(0.0);
  double weight = 0.0;
  for (size_t i = 0; i < texels.direction.size(); ++i) {
    const glm::dvec3& l = texels.direction[i];
    const double NoL = glm::dot(n, l);
    if (NoL <= 0.0) continue;
    const double NoH = glm::dot(n, glm::normalize(n + l));
    const double w = sheenDistribution(NoH, sheenRoughness) * sheenVisibility(1.0, NoL, sheenRoughness) * NoL *
                     texels.solidAngle[i];
    sum += texels.radiance[i] * w;
    weight += w;
  }
  return weight > 0.0 ? sum / weight : glm::dvec3(0.0);
}

}  // namespace pbr::reference
