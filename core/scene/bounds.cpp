#include "core/scene/bounds.hpp"

#include <algorithm>
#include <array>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>

namespace pbr {

void WorldBounds::add(const glm::vec3& p) {
  min = glm::min(min, p);
  max = glm::max(max, p);
}

void WorldBounds::add(const WorldBounds& b) {
  if (b.empty()) return;
  add(b.min);
  add(b.max);
}

bool overlaps(const WorldBounds& a, const WorldBounds& b) {
  return !a.empty() && !b.empty() && glm::all(glm::lessThanEqual(a.min, b.max)) &&
         glm::all(glm::lessThanEqual(b.min, a.max));
}

bool overlapsSphere(const WorldBounds& box, const glm::vec3& centre, float radius) {
  if (box.empty()) return false;
  const glm::vec3 d = centre - glm::clamp(centre, box.min, box.max);
  return glm::dot(d, d) <= radius * radius;
}

WorldBounds meshBounds(const MeshData& mesh, const glm::mat4& transform) {
  WorldBounds b;
  for (const Vertex& v : mesh.vertices) b.add(glm::vec3(transform * glm::vec4(v.position, 1.0f)));
  return b;
}

glm::ivec4 coveredRect(const WorldBounds& box, const glm::mat4& viewProjection, const glm::ivec4& viewport) {
  const glm::ivec4 none(viewport.x, viewport.y, 0, 0);
  if (box.empty()) return none;
  std::array<glm::vec4, 8> clip;
  bool behind = false;
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 corner(i & 1 ? box.max.x : box.min.x, i & 2 ? box.max.y : box.min.y,
                           i & 4 ? box.max.z : box.min.z);
    clip[size_t(i)] = viewProjection * glm::vec4(corner, 1.0f);
    behind = behind || !(clip[size_t(i)].w > 0.0f);
  }
  glm::vec2 lo(1e30f), hi(-1e30f);
  const auto add = [&](const glm::vec4& c) {
    const glm::vec2 ndc = glm::vec2(c) / c.w;
    lo = glm::min(lo, ndc);
    hi = glm::max(hi, ndc);
  };
  if (!behind) {
    for (const glm::vec4& c : clip) add(c);
  } else {
    // A box reaching behind a perspective view's eye: the part of it the rasterizer keeps, inside the depth range
    // 0 <= z <= w (glClipControl's zero-to-one; one of the two is the near plane): its corners there and its edges'
    // crossings of either plane that lie within the other, where w > 0.
    const auto kept = [](const glm::vec4& c) { return c.z >= 0.0f && c.w - c.z >= 0.0f && c.w > 0.0f; };
    for (int i = 0; i < 8; ++i) {
      const glm::vec4& a = clip[size_t(i)];
      if (kept(a)) add(a);
      for (const int bit : {1, 2, 4}) {
        if (i & bit) continue;
        const glm::vec4& b = clip[size_t(i | bit)];
        for (const glm::vec2 d : {glm::vec2(a.z, b.z), glm::vec2(a.w - a.z, b.w - b.z)}) {
          if ((d.x >= 0.0f) == (d.y >= 0.0f)) continue;
          glm::vec4 crossing = a + (b - a) * (d.x / (d.x - d.y));
          crossing.z = std::clamp(crossing.z, 0.0f, crossing.w);  // on the plane, not a rounding outside it
          if (kept(crossing)) add(crossing);
        }
      }
    }
    if (lo.x > hi.x) return none;
  }
  // NDC [-1, 1] onto the viewport's texels; a texel more each way for the rasterizer's rounding.
  const glm::vec2 origin(viewport.x, viewport.y), extent(viewport.z, viewport.w);
  const glm::vec2 first = glm::max(glm::floor(origin + (lo * 0.5f + 0.5f) * extent) - 1.0f, origin);
  const glm::vec2 last = glm::min(glm::ceil(origin + (hi * 0.5f + 0.5f) * extent) + 1.0f, origin + extent);
  if (!(first.x < last.x && first.y < last.y)) return none;
  return glm::ivec4(glm::ivec2(first), glm::ivec2(last - first));
}

glm::ivec4 joinRects(const glm::ivec4& a, const glm::ivec4& b) {
  if (emptyRect(a)) return b;
  if (emptyRect(b)) return a;
  const glm::ivec2 lo = glm::min(glm::ivec2(a), glm::ivec2(b));
  const glm::ivec2 hi = glm::max(glm::ivec2(a) + glm::ivec2(a.z, a.w), glm::ivec2(b) + glm::ivec2(b.z, b.w));
  return glm::ivec4(lo, hi - lo);
}

glm::ivec4 intersectRects(const glm::ivec4& a, const glm::ivec4& b) {
  const glm::ivec2 lo = glm::max(glm::ivec2(a), glm::ivec2(b));
  const glm::ivec2 hi = glm::min(glm::ivec2(a) + glm::ivec2(a.z, a.w), glm::ivec2(b) + glm::ivec2(b.z, b.w));
  return glm::ivec4(lo, glm::max(hi - lo, glm::ivec2(0)));
}

FrustumPlanes frustumPlanes(const glm::mat4& m) {
  const glm::vec4 r0(m[0][0], m[1][0], m[2][0], m[3][0]), r1(m[0][1], m[1][1], m[2][1], m[3][1]),
      r2(m[0][2], m[1][2], m[2][2], m[3][2]), r3(m[0][3], m[1][3], m[2][3], m[3][3]);
  return {r3 + r0, r3 - r0, r3 + r1, r3 - r1, r2, r3 - r2};
}

bool outsideFrustum(const FrustumPlanes& planes, const WorldBounds& box) {
  if (box.empty()) return true;
  for (const glm::vec4& p : planes) {
    // The box's corner furthest along the plane's normal.
    const glm::vec3 far(p.x >= 0.0f ? box.max.x : box.min.x, p.y >= 0.0f ? box.max.y : box.min.y,
                        p.z >= 0.0f ? box.max.z : box.min.z);
    if (glm::dot(glm::vec3(p), far) + p.w < 0.0f) return true;
  }
  return false;
}

}  // namespace pbr
