#include "reference/cube_map_geometry.hpp"

#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace pbr::reference {

CubeCoord cubeCoord(const glm::dvec3& d) {
  const glm::dvec3 a = glm::abs(d);
  double sc, tc, ma;
  int face;
  if (a.x >= a.y && a.x >= a.z) {
    face = d.x > 0 ? 0 : 1;
    sc = d.x > 0 ? -d.z : d.z;
    tc = -d.y;
    ma = a.x;
  } else if (a.y >= a.z) {
    face = d.y > 0 ? 2 : 3;
    sc = d.x;
    tc = d.y > 0 ? d.z : -d.z;
    ma = a.y;
  } else {
    face = d.z > 0 ? 4 : 5;
    sc = d.z > 0 ? d.x : -d.x;
    tc = -d.y;
    ma = a.z;
  }
  return {face, glm::dvec2(0.5 * (sc / ma + 1.0), 0.5 * (tc / ma + 1.0))};
}

glm::dvec3 cubeTexelDirection(int face, int x, int y, int size) {
  const double sc = 2.0 * (x + 0.5) / size - 1.0, tc = 2.0 * (y + 0.5) / size - 1.0;
  glm::dvec3 d;
  switch (face) {
    case 0: d = {1.0, -tc, -sc}; break;
    case 1: d = {-1.0, -tc, sc}; break;
    case 2: d = {sc, 1.0, tc}; break;
    case 3: d = {sc, -1.0, -tc}; break;
    case 4: d = {sc, -tc, 1.0}; break;
    default: d = {-sc, -tc, -1.0}; break;
  }
  return glm::normalize(d);
}

double cubeTexelSolidAngle(int x, int y, int size) {
  const auto area = [](double u, double v) { return std::atan2(u * v, std::sqrt(u * u + v * v + 1.0)); };
  const double x0 = 2.0 * x / size - 1.0, x1 = 2.0 * (x + 1) / size - 1.0;
  const double y0 = 2.0 * y / size - 1.0, y1 = 2.0 * (y + 1) / size - 1.0;
  return area(x0, y0) - area(x0, y1) - area(x1, y0) + area(x1, y1);
}

}  // namespace pbr::reference
