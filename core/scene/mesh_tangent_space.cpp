#include "core/scene/mesh_tangent_space.hpp"

#include <cmath>

#include <glm/geometric.hpp>

namespace pbr {

namespace {

bool usable(const glm::vec3& v) {
  const float len2 = glm::dot(v, v);
  return std::isfinite(len2) && len2 > 1e-24f;
}

// Any unit vector perpendicular to unit n.
glm::vec3 perpendicular(const glm::vec3& n) {
  const glm::vec3 axis = std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  return glm::normalize(glm::cross(axis, n));
}

}  // namespace

void makeFlatNormals(MeshData& mesh) {
  MeshData flat;
  flat.vertices.reserve(mesh.indices.size());
  flat.indices.reserve(mesh.indices.size());
  for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    const Vertex* v[3] = {&mesh.vertices[mesh.indices[i]], &mesh.vertices[mesh.indices[i + 1]],
                          &mesh.vertices[mesh.indices[i + 2]]};
    const glm::vec3 face = glm::cross(v[1]->position - v[0]->position, v[2]->position - v[0]->position);
    // A degenerate triangle covers no pixel; any unit normal keeps the shading finite.
    const glm::vec3 n = usable(face) ? glm::normalize(face) : glm::vec3(0, 1, 0);
    for (size_t k = 0; k < 3; ++k) {
      Vertex out = *v[k];
      out.normal = n;
      flat.indices.push_back(static_cast<uint32_t>(flat.vertices.size()));
      flat.vertices.push_back(out);
      const uint32_t source = mesh.indices[i + k];
      if (!mesh.colors.empty()) flat.colors.push_back(mesh.colors[source]);
      if (!mesh.uv1.empty()) flat.uv1.push_back(mesh.uv1[source]);
    }
  }
  mesh = std::move(flat);
}

void repairNormals(MeshData& mesh) {
  std::vector<glm::vec3> sums;
  for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    const uint32_t a = mesh.indices[i], b = mesh.indices[i + 1], c = mesh.indices[i + 2];
    if (usable(mesh.vertices[a].normal) && usable(mesh.vertices[b].normal) && usable(mesh.vertices[c].normal)) continue;
    if (sums.empty()) sums.assign(mesh.vertices.size(), glm::vec3(0.0f));
    // The unnormalised cross product weights each triangle by its area.
    const glm::vec3 face = glm::cross(mesh.vertices[b].position - mesh.vertices[a].position,
                                      mesh.vertices[c].position - mesh.vertices[a].position);
    if (!usable(face)) continue;
    for (const uint32_t k : {a, b, c}) sums[k] += face;
  }
  if (sums.empty()) return;
  for (size_t k = 0; k < mesh.vertices.size(); ++k) {
    glm::vec3& n = mesh.vertices[k].normal;
    if (!usable(n)) n = usable(sums[k]) ? glm::normalize(sums[k]) : glm::vec3(0, 1, 0);
  }
}

// Lengyel 2001, "Computing Tangent Space Basis Vectors for an Arbitrary Mesh".
void generateTangents(MeshData& mesh) {
  std::vector<glm::vec3> tangents(mesh.vertices.size(), glm::vec3(0.0f));
  std::vector<glm::vec3> bitangents(mesh.vertices.size(), glm::vec3(0.0f));
  for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    const uint32_t k[3] = {mesh.indices[i], mesh.indices[i + 1], mesh.indices[i + 2]};
    const Vertex& v0 = mesh.vertices[k[0]];
    const glm::vec3 e1 = mesh.vertices[k[1]].position - v0.position;
    const glm::vec3 e2 = mesh.vertices[k[2]].position - v0.position;
    const glm::vec2 d1 = mesh.vertices[k[1]].uv - v0.uv;
    const glm::vec2 d2 = mesh.vertices[k[2]].uv - v0.uv;
    const float det = d1.x * d2.y - d2.x * d1.y;
    if (!std::isfinite(det) || std::abs(det) < 1e-20f) continue;  // no UV area: no direction to follow
    const glm::vec3 dPdu = (e1 * d2.y - e2 * d1.y) / det;
    const glm::vec3 dPdv = (e2 * d1.x - e1 * d2.x) / det;
    if (!std::isfinite(glm::dot(dPdu, dPdu)) || !std::isfinite(glm::dot(dPdv, dPdv))) continue;
    for (const uint32_t v : k) {
      tangents[v] += dPdu;
      // glTF's v runs down the image while a normal map's +Y points up it (OpenGL convention, what MikkTSpace
      // computes for glTF exporters), so the bitangent is -dP/dv.
      bitangents[v] -= dPdv;
    }
  }
  for (size_t v = 0; v < mesh.vertices.size(); ++v) {
    Vertex& vertex = mesh.vertices[v];
    const glm::vec3 n = glm::normalize(vertex.normal);
    const glm::vec3 t = tangents[v] - n * glm::dot(n, tangents[v]);
    if (!usable(t)) {
      vertex.tangent = glm::vec4(perpendicular(n), 1.0f);
      continue;
    }
    const float w = glm::dot(glm::cross(n, t), bitangents[v]) < 0.0f ? -1.0f : 1.0f;
    vertex.tangent = glm::vec4(glm::normalize(t), w);
  }
}

}  // namespace pbr
