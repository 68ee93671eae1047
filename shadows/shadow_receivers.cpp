#include "shadows/shadow_receivers.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include <glm/common.hpp>

namespace pbr {

namespace {

// The world box of a view-space box: its centre transformed, its half extent through the rotation's absolute
// values (Arvo 1990, "Transforming Axis-Aligned Bounding Boxes").
WorldBounds worldBox(const ViewSpaceBox& b, const glm::mat4& inverseView) {
  const glm::vec3 centre = 0.5f * (b.min + b.max), half = 0.5f * (b.max - b.min);
  const glm::vec3 c = glm::vec3(inverseView * glm::vec4(centre, 1.0f));
  const glm::mat3 r(inverseView);
  const glm::vec3 e = glm::abs(r[0]) * half.x + glm::abs(r[1]) * half.y + glm::abs(r[2]) * half.z;
  const float magnitude = std::max({std::abs(c.x) + e.x, std::abs(c.y) + e.y, std::abs(c.z) + e.z});
  const glm::vec3 pad(1e-4f * magnitude + 1e-6f);
  WorldBounds w;
  w.add(c - e - pad);
  w.add(c + e + pad);
  return w;
}

}  // namespace

ShadowReceivers::ShadowReceivers(const std::vector<ViewSpaceBox>& boxes, const glm::mat4& inverseView) {
  std::map<uint32_t, size_t> tileIndex;
  nearDepth_ = 1e30f;
  farDepth_ = -1e30f;
  for (const ViewSpaceBox& b : boxes) {
    const auto [it, added] = tileIndex.emplace(b.tile, tiles_.size());
    if (added) tiles_.emplace_back();
    Tile& tile = tiles_[it->second];
    // View space looks down -z: a point's depth is -z.
    const Cluster c{worldBox(b, inverseView), -b.max.z, -b.min.z};
    tile.box.add(c.box);
    tile.clusters.push_back(c);
    nearDepth_ = std::min(nearDepth_, c.nearDepth);
    farDepth_ = std::max(farDepth_, c.farDepth);
  }
}

bool ShadowReceivers::meets(const glm::vec4& sphere, const FrustumPlanes& planes) const {
  const glm::vec3 centre(sphere);
  for (const Tile& tile : tiles_) {
    if (!overlapsSphere(tile.box, centre, sphere.w) || outsideFrustum(planes, tile.box)) continue;
    for (const Cluster& c : tile.clusters) {
      if (overlapsSphere(c.box, centre, sphere.w) && !outsideFrustum(planes, c.box)) return true;
    }
  }
  return false;
}

uint32_t ShadowReceivers::meetsViews(const glm::vec4& sphere, const std::vector<FrustumPlanes>& views) const {
  const glm::vec3 centre(sphere);
  const uint32_t all = views.size() >= 32 ? ~0u : (1u << views.size()) - 1u;
  uint32_t met = 0;
  for (const Tile& tile : tiles_) {
    if (!overlapsSphere(tile.box, centre, sphere.w)) continue;
    uint32_t open = 0;  // the views not met yet that the tile is not wholly outside of
    for (size_t v = 0; v < views.size(); ++v) {
      if ((met >> v & 1u) == 0u && !outsideFrustum(views[v], tile.box)) open |= 1u << v;
    }
    for (const Cluster& c : tile.clusters) {
      if (open == 0u) break;
      if (!overlapsSphere(c.box, centre, sphere.w)) continue;
      for (uint32_t bits = open; bits != 0u; bits &= bits - 1u) {
        const int v = __builtin_ctz(bits);
        if (!outsideFrustum(views[size_t(v)], c.box)) {
          met |= 1u << v;
          open &= ~(1u << v);
        }
      }
    }
    if (met == all) break;
  }
  return met;
}

bool ShadowReceivers::holdsDepth(float begin, float end) const {
  for (const Tile& tile : tiles_) {
    for (const Cluster& c : tile.clusters) {
      if (c.farDepth >= begin && c.nearDepth <= end) return true;
    }
  }
  return false;
}

}  // namespace pbr
