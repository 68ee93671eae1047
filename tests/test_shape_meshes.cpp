// The analytic shapes' meshes: every triangle winds counter-clockwise seen from outside, as back-face culling in
// the G-buffer pass assumes, so that a shape is never drawn inside out; and which meshes bound a solid
// (core/scene/closed_mesh.hpp), whose faces turned away from a light the shadow views leave out.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <utility>
#include <vector>
#include <cmath>

#include <glm/geometric.hpp>

#include "core/scene/closed_mesh.hpp"
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

namespace {

// A mesh from positions and counter-clockwise triangles, each triangle's corners their own vertices (as a mesh with
// flat normals has them), so that only positions say which edges meet.
pbr::MeshData splitMesh(const std::vector<glm::vec3>& positions, const std::vector<std::array<uint32_t, 3>>& faces) {
  pbr::MeshData m;
  for (const std::array<uint32_t, 3>& f : faces) {
    for (const uint32_t i : f) {
      m.indices.push_back(uint32_t(m.vertices.size()));
      m.vertices.push_back({positions[i], glm::vec3(0.0f), glm::vec2(0.0f), glm::vec4(0.0f)});
    }
  }
  return m;
}

// A tetrahedron whose faces wind counter-clockwise seen from outside.
const std::vector<glm::vec3> kTetrahedron = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
const std::vector<std::array<uint32_t, 3>> kTetrahedronFaces = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};

}  // namespace

TEST_CASE("closed meshes: the shapes and solids are closed and outward, open or doubled surfaces are not") {
  CHECK(pbr::meshClosure(pbr::makeBoxMesh()) == pbr::MeshClosure::Outward);  // faces split at every edge
  for (const int segments : {8, 16, 32, 64}) {
    CAPTURE(segments);  // a seam of split vertices and pole triangles without area
    CHECK(pbr::meshClosure(pbr::makeSphereMesh(segments, segments / 2)) == pbr::MeshClosure::Outward);
  }
  CHECK(pbr::meshClosure(pbr::makePlaneMesh()) == pbr::MeshClosure::Open);
  CHECK(pbr::meshClosure(splitMesh(kTetrahedron, kTetrahedronFaces)) == pbr::MeshClosure::Outward);

  // Every face wound the other way: closed, looking in.
  std::vector<std::array<uint32_t, 3>> reversed = kTetrahedronFaces;
  for (std::array<uint32_t, 3>& f : reversed) std::swap(f[1], f[2]);
  CHECK(pbr::meshClosure(splitMesh(kTetrahedron, reversed)) == pbr::MeshClosure::Inward);
  // One face missing, or one wound the other way: its edges are unmatched.
  CHECK(pbr::meshClosure(splitMesh(kTetrahedron, {kTetrahedronFaces.begin(), kTetrahedronFaces.end() - 1})) ==
        pbr::MeshClosure::Open);
  std::vector<std::array<uint32_t, 3>> flipped = kTetrahedronFaces;
  std::swap(flipped[3][1], flipped[3][2]);
  CHECK(pbr::meshClosure(splitMesh(kTetrahedron, flipped)) == pbr::MeshClosure::Open);
  // A card drawn from both sides: every edge matched, but no inside.
  CHECK(pbr::meshClosure(splitMesh(kTetrahedron, {{0, 1, 2}, {0, 2, 1}})) == pbr::MeshClosure::Open);
  // A crack: one corner of one face a ten-thousandth of the size away from where its neighbours have it. Rounding
  // a billionth apart, as a seam computed from sin(2 pi) is, closes nothing.
  pbr::MeshData cracked = splitMesh(kTetrahedron, kTetrahedronFaces);
  cracked.vertices[0].position.y += 1e-4f;
  CHECK(pbr::meshClosure(cracked) == pbr::MeshClosure::Open);
  cracked.vertices[0].position.y = 1e-9f;
  CHECK(pbr::meshClosure(cracked) == pbr::MeshClosure::Outward);
  // Two solids in one mesh, as a glTF primitive may hold: still closed.
  std::vector<glm::vec3> two = kTetrahedron;
  for (const glm::vec3& p : kTetrahedron) two.push_back(p + glm::vec3(3.0f, 0.0f, 0.0f));
  std::vector<std::array<uint32_t, 3>> twoFaces = kTetrahedronFaces;
  for (const std::array<uint32_t, 3>& f : kTetrahedronFaces) twoFaces.push_back({f[0] + 4, f[1] + 4, f[2] + 4});
  CHECK(pbr::meshClosure(splitMesh(two, twoFaces)) == pbr::MeshClosure::Outward);
}
