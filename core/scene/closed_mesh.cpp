#include "core/scene/closed_mesh.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>

namespace pbr {

namespace {

// Each vertex's position number: positions within `cell` of each other share one, as far as rounding them to a grid
// of that step puts them in one cell (two on either side of a cell's edge stay apart, and the mesh then counts as
// open: a safe answer). A seam computed twice from sin and cos of 0 and 2 pi, as generated spheres have it, is
// closed; a gap of a millionth of the mesh's size lets no light through that a shadow map could show.
std::vector<uint32_t> weldPositions(const std::vector<Vertex>& vertices, const glm::dvec3& lo, double cell) {
  struct Key {
    std::array<int64_t, 3> cell;
    uint32_t vertex;
  };
  std::vector<Key> keys(vertices.size());
  for (uint32_t i = 0; i < vertices.size(); ++i) {
    const glm::dvec3 q = (glm::dvec3(vertices[i].position) - lo) / cell;
    keys[i] = {{std::llround(q.x), std::llround(q.y), std::llround(q.z)}, i};
  }
  std::sort(keys.begin(), keys.end(), [](const Key& a, const Key& b) { return a.cell < b.cell; });
  std::vector<uint32_t> welded(vertices.size());
  uint32_t id = 0;
  for (size_t i = 0; i < keys.size(); ++i) {
    if (i > 0 && keys[i].cell != keys[i - 1].cell) ++id;
    welded[keys[i].vertex] = id;
  }
  return welded;
}

}  // namespace

MeshClosure meshClosure(const MeshData& mesh) {
  if (mesh.indices.size() < 3 || mesh.vertices.empty()) return MeshClosure::Open;
  glm::dvec3 lo(1e300), hi(-1e300);
  for (const Vertex& v : mesh.vertices) {
    lo = glm::min(lo, glm::dvec3(v.position));
    hi = glm::max(hi, glm::dvec3(v.position));
  }
  const glm::dvec3 e = hi - lo;
  const double boxVolume = e.x * e.y * e.z;
  if (!(boxVolume > 0.0) || !std::isfinite(boxVolume)) return MeshClosure::Open;
  const std::vector<uint32_t> welded = weldPositions(mesh.vertices, lo, 1e-6 * glm::length(e));
  // Every edge as (lower position, higher position) and +1 or -1 for the way it runs; a closed mesh's sum to 0.
  std::vector<std::pair<uint64_t, int>> edges;
  edges.reserve(mesh.indices.size());
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    for (size_t k = 0; k < 3; ++k) {
      const uint32_t a = welded[mesh.indices[t + k]], b = welded[mesh.indices[t + (k + 1) % 3]];
      if (a == b) continue;
      edges.push_back({uint64_t(std::min(a, b)) << 32 | std::max(a, b), a < b ? 1 : -1});
    }
  }
  std::sort(edges.begin(), edges.end());
  for (size_t i = 0; i < edges.size();) {
    int sum = 0;
    size_t j = i;
    for (; j < edges.size() && edges[j].first == edges[i].first; ++j) sum += edges[j].second;
    if (sum != 0) return MeshClosure::Open;
    i = j;
  }
  // Signed volume by the divergence theorem, sum of a . (b x c) / 6, about the box's centre for precision.
  const glm::dvec3 centre = 0.5 * (lo + hi);
  double volume = 0.0;
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const glm::dvec3 a = glm::dvec3(mesh.vertices[mesh.indices[t]].position) - centre;
    const glm::dvec3 b = glm::dvec3(mesh.vertices[mesh.indices[t + 1]].position) - centre;
    const glm::dvec3 c = glm::dvec3(mesh.vertices[mesh.indices[t + 2]].position) - centre;
    volume += glm::dot(a, glm::cross(b, c)) / 6.0;
  }
  if (!(std::abs(volume) > 1e-6 * boxVolume)) return MeshClosure::Open;
  return volume > 0.0 ? MeshClosure::Outward : MeshClosure::Inward;
}

}  // namespace pbr
