#include "core/scene/caster_plane.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace pbr {

std::optional<CasterPlane> casterPlane(const MeshData& mesh, const glm::mat4& transform) {
  if (mesh.vertices.size() < 3 || mesh.indices.size() < 3) return std::nullopt;
  const glm::dmat4 m(transform);
  const auto world = [&](uint32_t i) { return glm::dvec3(m * glm::dvec4(glm::dvec3(mesh.vertices[i].position), 1.0)); };
  glm::dvec3 lo(1e300), hi(-1e300);
  for (uint32_t i = 0; i < mesh.vertices.size(); ++i) {
    lo = glm::min(lo, world(i));
    hi = glm::max(hi, world(i));
  }
  const double diagonal = glm::length(hi - lo);
  if (!(diagonal > 0.0)) return std::nullopt;
  // A curved mesh is turned away early: its vertices soon leave the plane of its first triangle of some area by a
  // hundredth of its size, which a flat mesh's never do.
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const glm::dvec3 a = world(mesh.indices[t]);
    const glm::dvec3 n = glm::cross(world(mesh.indices[t + 1]) - a, world(mesh.indices[t + 2]) - a);
    if (!(glm::length(n) > 1e-6 * diagonal * diagonal)) continue;
    const glm::dvec3 unit = glm::normalize(n);
    for (uint32_t i = 0; i < mesh.vertices.size(); ++i) {
      if (std::abs(glm::dot(unit, world(i) - a)) > 1e-2 * diagonal) return std::nullopt;
    }
    break;
  }
  // The largest triangle's normal: the best-conditioned one.
  glm::dvec3 normal(0.0), origin(0.0);
  double largest = 0.0;
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const glm::dvec3 a = world(mesh.indices[t]);
    const glm::dvec3 n = glm::cross(world(mesh.indices[t + 1]) - a, world(mesh.indices[t + 2]) - a);
    const double area = glm::dot(n, n);
    if (area > largest) {
      largest = area;
      normal = n;
      origin = a;
    }
  }
  if (!(largest > 0.0)) return std::nullopt;
  normal = glm::normalize(normal);
  const double offset = -glm::dot(normal, origin);
  double off = 0.0, magnitude = 0.0;
  for (uint32_t i = 0; i < mesh.vertices.size(); ++i) {
    const glm::dvec3 p = world(i);
    off = std::max(off, std::abs(glm::dot(normal, p) + offset));
    magnitude = std::max({magnitude, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  }
  if (off > 1e-5 * diagonal) return std::nullopt;
  // The vertices reach the GPU as floats transformed in float: a few ulps of the coordinates' magnitude more.
  return CasterPlane{glm::vec4(glm::vec3(normal), float(offset)), float(off + 1e-6 * magnitude)};
}

bool planeMayShadow(const CasterPlane& plane, uint32_t sides, size_t index, const glm::vec4& position) {
  const glm::vec3 n(plane.plane);
  // A point light's signed distance; for a directional one the cosine between the normal and the way to the light.
  const float side = position.w != 0.0f ? glm::dot(n, glm::vec3(position)) + plane.plane.w
                                         : -glm::dot(n, glm::vec3(position));
  const float onPlane = position.w != 0.0f ? plane.thickness : 1e-6f;
  if (side > onPlane) return receiversBelow(sides, index);
  if (side < -onPlane) return receiversAbove(sides, index);
  return true;
}

}  // namespace pbr
