// The analytic shapes' meshes: every triangle winds counter-clockwise seen from outside, as back-face culling in
// the G-buffer pass assumes, so that a shape is never drawn inside out.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "core/scene/mesh.hpp"

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

TEST_CASE("shape meshes: a tessellated sphere lies inside the sphere by no more than sphereTessellationDepth") {
  // The depth of each facet below the sphere of radius 0.5, measured here as 0.5 minus the distance from the centre
  // to the facet's plane (the plane's nearest point lies on the facet: a UV sphere's quads are planar trapezoids
  // symmetric about their centre); the bound must hold and be close (within 15 %) for the deepest facet.
  for (const int segments : {8, 16, 32, 64}) {
    CAPTURE(segments);
    const pbr::MeshData mesh = pbr::makeSphereMesh(segments, segments / 2);
    float deepest = 0.0f;
    for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
      const glm::vec3 a = mesh.vertices[mesh.indices[i]].position, b = mesh.vertices[mesh.indices[i + 1]].position,
                      c = mesh.vertices[mesh.indices[i + 2]].position;
      const glm::vec3 n = glm::cross(b - a, c - a);
      if (glm::length(n) < 1e-9f) continue;
      deepest = std::max(deepest, 0.5f - std::abs(glm::dot(glm::normalize(n), a)));
    }
    const float bound = pbr::sphereTessellationDepth(0.5f, segments);
    CHECK(deepest <= bound * 1.0001f);
    CHECK(deepest >= bound * 0.85f);
  }
}
