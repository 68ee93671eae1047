#pragma once
#include <array>
#include <cstdint>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "core/scene/mesh.hpp"

namespace pbr {

// An axis-aligned box in world space; empty when min > max.
struct WorldBounds {
  glm::vec3 min{1e30f};
  glm::vec3 max{-1e30f};
  bool empty() const { return min.x > max.x; }
  void add(const glm::vec3& p);
  void add(const WorldBounds& b);
};

// A box of visible surface points in view space (the camera looking down -z), and the screen tile it lies in: what
// the cluster occupancy measures (lighting/light_clusters.hpp), handed to the shadow planner.
struct ViewSpaceBox {
  glm::vec3 min, max;
  uint32_t tile;
};

// Whether two boxes share a point; an empty box meets nothing.
bool overlaps(const WorldBounds& a, const WorldBounds& b);

// Whether the box meets the sphere of `centre` and `radius` (its nearest point no farther than the radius).
bool overlapsSphere(const WorldBounds& box, const glm::vec3& centre, float radius);

// The world box of a mesh's vertices under `transform`.
WorldBounds meshBounds(const MeshData& mesh, const glm::mat4& transform);

// The texels of `viewport` (x, y, width, height) that the box's projection through `viewProjection` may cover: the
// rectangle of its corners' projections, a texel wider on each side, within the viewport; of a box reaching behind a
// perspective view's eye (w <= 0), of its part within the depth range 0 <= z <= w (glClipControl's zero-to-one);
// width 0 where it misses the viewport.
glm::ivec4 coveredRect(const WorldBounds& box, const glm::mat4& viewProjection, const glm::ivec4& viewport);
// Texel rectangles (x, y, width, height; a width or height of 0 is empty): the smallest holding both, and their
// common texels (empty where they share none).
inline bool emptyRect(const glm::ivec4& r) { return r.z <= 0 || r.w <= 0; }
glm::ivec4 joinRects(const glm::ivec4& a, const glm::ivec4& b);
glm::ivec4 intersectRects(const glm::ivec4& a, const glm::ivec4& b);

// The planes (a.x + b.y + c.z + d >= 0 inside) of the clip-space frustum of `m`: x and y in [-w, w], z in [0, w]
// (glClipControl's zero-to-one range, either depth direction) (Gribb & Hartmann 2001, "Fast Extraction of Viewing
// Frustum Planes from the World-View-Projection Matrix").
using FrustumPlanes = std::array<glm::vec4, 6>;
FrustumPlanes frustumPlanes(const glm::mat4& m);

// True when the box lies wholly outside one of the planes: nothing in it can be in the frustum. Conservative: a box
// near a corner may pass without meeting the frustum.
bool outsideFrustum(const FrustumPlanes& planes, const WorldBounds& box);

}  // namespace pbr
