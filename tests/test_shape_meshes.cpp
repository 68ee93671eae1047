// The analytic shapes' meshes: every triangle winds counter-clockwise seen from outside, as back-face culling in
// the G-buffer pass assumes, so that a shape is never drawn inside out.
#include <doctest/doctest.h>

#include <glm/geometric.hpp>

#include "core/mesh.hpp"

namespace {

// Triangles whose winding (the normal it implies) disagrees with the normals the vertices carry.
size_t inwardTriangles(const pbr::MeshData& mesh) {
  size_t inward = 0;
  for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    const pbr::Vertex& a = mesh.vertices[mesh.indices[i]];
    const pbr::Vertex& b = mesh.vertices[mesh.indices[i + 1]];
    const pbr::Vertex& c = mesh.vertices[mesh.indices[i + 2]];
    const glm::vec3 wound = glm::cross(b.position - a.position, c.position - a.position);
    // The sphere's pole triangles have no area, hence no winding.
    if (glm::length(wound) < 1e-9f) continue;
    inward += glm::dot(wound, a.normal + b.normal + c.normal) > 0.0f ? 0 : 1;
  }
  return inward;
}

}  // namespace

TEST_CASE("shape meshes: plane, sphere and box triangles wind counter-clockwise seen from outside") {
  const pbr::MeshData plane = pbr::makePlaneMesh(), sphere = pbr::makeSphereMesh(), box = pbr::makeBoxMesh();
  CHECK(inwardTriangles(plane) == 0);
  CHECK(inwardTriangles(sphere) == 0);
  CHECK(inwardTriangles(box) == 0);
  CHECK(box.indices.size() == 36);
}
