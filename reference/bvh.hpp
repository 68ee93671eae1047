#pragma once
#include <cstdint>
#include <limits>
#include <vector>

#include <glm/vec3.hpp>

#include "reference/raycast.hpp"

namespace pbr::reference {

struct Aabb {
  dvec3 min{std::numeric_limits<double>::infinity()};
  dvec3 max{-std::numeric_limits<double>::infinity()};
  void grow(const dvec3& p);
  void grow(const Aabb& b);
  // The ray parameter interval [tMin, tMax] clipped to the box (slab test, Kay & Kajiya 1986); false if empty.
  bool clip(const dvec3& origin, const dvec3& inverseDirection, double& tMin, double& tMax) const;
  double diagonal() const;  // 0 for an empty box
};

// A bounding volume hierarchy over primitives given by their boxes, split at the median centroid along the widest
// axis: the reference needs correct closest hits in seconds, not the best tree.
class Bvh {
 public:
  Bvh() = default;
  explicit Bvh(const std::vector<Aabb>& boxes);

  // Calls `hit(primitive, tMax)` for each primitive whose box the ray enters within [tMin, tMax], nearer subtrees
  // first; `hit` returns the distance of its hit if it is closer than tMax, else tMax, so farther boxes are skipped.
  template <class Visit>
  void traverse(const Ray& ray, double tMin, double tMax, Visit hit) const;
  // Whether `hits(primitive)` holds for a primitive whose box the ray enters within [tMin, tMax]; returns at the
  // first that does. Any hit ends the search, so the subtrees are visited in a fixed order, without sorting.
  template <class Test>
  bool any(const Ray& ray, double tMin, double tMax, Test hits) const;

 private:
  static constexpr uint32_t kLeafSize = 4;
  struct Node {
    Aabb box;
    uint32_t first = 0;  // leaf: first entry of order_; inner node: the first of its two adjacent children
    uint32_t count = 0;  // primitives of a leaf, 0 for an inner node
  };
  void build(uint32_t node, uint32_t first, uint32_t count, const std::vector<Aabb>& boxes,
             const std::vector<dvec3>& centroids);
  std::vector<Node> nodes_;
  std::vector<uint32_t> order_;  // primitive indices, each leaf's contiguous
};

template <class Visit>
void Bvh::traverse(const Ray& ray, double tMin, double tMax, Visit hit) const {
  if (nodes_.empty()) return;
  const dvec3 inverse = 1.0 / ray.direction;
  auto entry = [&](uint32_t node) {
    double t0 = tMin, t1 = tMax;
    return nodes_[node].box.clip(ray.origin, inverse, t0, t1) ? t0 : std::numeric_limits<double>::infinity();
  };
  uint32_t stack[64];  // a median split keeps the depth at log2 of the primitive count
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const uint32_t index = stack[--top];
    if (entry(index) == std::numeric_limits<double>::infinity()) continue;  // missed, or behind a hit found since
    const Node& node = nodes_[index];
    if (node.count > 0) {
      for (uint32_t i = node.first; i < node.first + node.count; ++i) tMax = hit(order_[i], tMax);
      continue;
    }
    // The child the ray enters first is visited first: its hits shrink tMax, which may then skip the other.
    const bool firstNearer = entry(node.first) <= entry(node.first + 1);
    stack[top++] = firstNearer ? node.first + 1 : node.first;
    stack[top++] = firstNearer ? node.first : node.first + 1;
  }
}

template <class Test>
bool Bvh::any(const Ray& ray, double tMin, double tMax, Test hits) const {
  if (nodes_.empty()) return false;
  const dvec3 inverse = 1.0 / ray.direction;
  uint32_t stack[64];  // as in traverse()
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    double t0 = tMin, t1 = tMax;
    if (!node.box.clip(ray.origin, inverse, t0, t1)) continue;
    if (node.count == 0) {
      stack[top++] = node.first + 1;
      stack[top++] = node.first;
      continue;
    }
    for (uint32_t i = node.first; i < node.first + node.count; ++i) {
      if (hits(order_[i])) return true;
    }
  }
  return false;
}

}  // namespace pbr::reference
