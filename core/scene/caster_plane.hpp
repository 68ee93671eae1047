#pragma once
#include <cstddef>
#include <cstdint>
#include <optional>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "core/scene/mesh.hpp"

namespace pbr {

// A caster whose triangles all lie in one plane (a floor, a wall, a leaf card). From a light off its plane it can
// only hide points on the plane's other side: the segment from a point to the light crosses the plane only there.
// A frame whose visible surfaces all lie on the light's side (or on the plane) leaves it out of that light's
// shadow views, where it would only fill texels (the cluster occupancy finds the sides, lighting/light_clusters).
struct CasterPlane {
  glm::vec4 plane{0.0f};   // world: xyz the unit normal, w the offset (n.x + w = 0 on the plane)
  float thickness = 0.0f;  // the most a vertex lies off the plane, float rounding included
};

// Planes the occupancy pass tests each visible point against, at most: a 32-bit word holds their sides.
constexpr size_t kMaxCasterPlanes = 16;

// The plane of a mesh under `transform` when every vertex lies within 1e-5 of its box's diagonal of the plane of
// its largest triangle; none for a mesh with a vertex off it, or without a triangle of area.
std::optional<CasterPlane> casterPlane(const MeshData& mesh, const glm::mat4& transform);

// Which sides of the frame's caster planes visible surface points lie on, as the occupancy pass reports them: bit
// 2i set when some point lies beyond plane i's tolerance on its normal's side, bit 2i + 1 on the other.
inline bool receiversAbove(uint32_t sides, size_t plane) { return (sides >> (2 * plane) & 1u) != 0u; }
inline bool receiversBelow(uint32_t sides, size_t plane) { return (sides >> (2 * plane + 1) & 1u) != 0u; }

// Whether plane i may hide a visible point from a light at `position` (w 1), or from a directional light whose
// light travels along `position`'s xyz (w 0): some visible point lies on the side away from the light. A light on
// the plane (within its thickness) or grazing it may.
bool planeMayShadow(const CasterPlane& plane, uint32_t sides, size_t index, const glm::vec4& position);

}  // namespace pbr
