#include "reference/bvh.hpp"

#include <algorithm>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace pbr::reference {

void Aabb::grow(const dvec3& p) {
  min = glm::min(min, p);
  max = glm::max(max, p);
}

void Aabb::grow(const Aabb& b) {
  min = glm::min(min, b.min);
  max = glm::max(max, b.max);
}

bool Aabb::clip(const dvec3& origin, const dvec3& inverseDirection, double& tMin, double& tMax) const {
  for (int i = 0; i < 3; ++i) {
    const double t0 = (min[i] - origin[i]) * inverseDirection[i];
    const double t1 = (max[i] - origin[i]) * inverseDirection[i];
    // A NaN (a ray parallel to the slab starting on its plane) fails every comparison and so leaves the interval
    // as it is: such a box is visited rather than missed.
    if (t0 < t1) {
      if (t0 > tMin) tMin = t0;
      if (t1 < tMax) tMax = t1;
    } else {
      if (t1 > tMin) tMin = t1;
      if (t0 < tMax) tMax = t0;
    }
  }
  return tMin <= tMax;
}

double Aabb::diagonal() const { return min.x <= max.x ? glm::length(max - min) : 0.0; }

Bvh::Bvh(const std::vector<Aabb>& boxes) {
  if (boxes.empty()) return;
  std::vector<dvec3> centroids;
  centroids.reserve(boxes.size());
  for (const Aabb& b : boxes) centroids.push_back(0.5 * (b.min + b.max));
  order_.resize(boxes.size());
  for (uint32_t i = 0; i < order_.size(); ++i) order_[i] = i;
  nodes_.emplace_back();
  build(0, 0, uint32_t(boxes.size()), boxes, centroids);
}

void Bvh::build(uint32_t node, uint32_t first, uint32_t count, const std::vector<Aabb>& boxes,
                const std::vector<dvec3>& centroids) {
  Aabb box, centres;
  for (uint32_t i = first; i < first + count; ++i) {
    box.grow(boxes[order_[i]]);
    centres.grow(centroids[order_[i]]);
  }
  nodes_[node].box = box;
  if (count <= kLeafSize) {
    nodes_[node].first = first;
    nodes_[node].count = count;
    return;
  }
  const dvec3 extent = centres.max - centres.min;
  const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
  const uint32_t half = count / 2;
  std::nth_element(order_.begin() + first, order_.begin() + first + half, order_.begin() + first + count,
                   [&](uint32_t a, uint32_t b) { return centroids[a][axis] < centroids[b][axis]; });
  const uint32_t children = uint32_t(nodes_.size());
  nodes_[node].first = children;
  nodes_.emplace_back();
  nodes_.emplace_back();
  build(children, first, half, boxes, centroids);
  build(children + 1, first + half, count - half, boxes, centroids);
}

}  // namespace pbr::reference
