#include "core/scene/mesh.hpp"

#include <cmath>

#include <glm/geometric.hpp>

namespace pbr {

MeshData makePlaneMesh() {
  MeshData m;
  const glm::vec3 n(0, 1, 0);
  const glm::vec4 t(1, 0, 0, 1);
  m.vertices = {{{-0.5f, 0, 0.5f}, n, {0, 0}, t},
                {{0.5f, 0, 0.5f}, n, {1, 0}, t},
                {{0.5f, 0, -0.5f}, n, {1, 1}, t},
                {{-0.5f, 0, -0.5f}, n, {0, 1}, t}};
  m.indices = {0, 1, 2, 0, 2, 3};
  return m;
}

MeshData makeSphereMesh(int segments, int rings) {
  MeshData m;
  const float pi = 3.14159265358979f;
  for (int r = 0; r <= rings; ++r) {
    const float v = static_cast<float>(r) / rings;
    const float theta = v * pi;
    for (int s = 0; s <= segments; ++s) {
      const float u = static_cast<float>(s) / segments;
      const float phi = u * 2.0f * pi;
      const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta), -std::sin(theta) * std::sin(phi));
      const glm::vec4 t(-std::sin(phi), 0.0f, -std::cos(phi), 1.0f);
      m.vertices.push_back({0.5f * n, n, {u, 1.0f - v}, t});
    }
  }
  const uint32_t stride = static_cast<uint32_t>(segments + 1);
  for (uint32_t r = 0; r < static_cast<uint32_t>(rings); ++r) {
    for (uint32_t s = 0; s < static_cast<uint32_t>(segments); ++s) {
      const uint32_t a = r * stride + s, b = a + stride;
      m.indices.insert(m.indices.end(), {a, b, a + 1, a + 1, b, b + 1});
    }
  }
  return m;
}

float sphereTessellationDepth(float radius, int segments) {
  const float s = std::sin(3.14159265f / static_cast<float>(segments));
  return radius * s * s;
}

MeshData makeBoxMesh() {
  MeshData m;
  const glm::vec3 normals[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (const glm::vec3& n : normals) {
    // Two tangents with t x b = n.
    const glm::vec3 t = std::abs(n.y) > 0.5f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    const glm::vec3 b = glm::cross(n, t);
    const uint32_t base = static_cast<uint32_t>(m.vertices.size());
    const glm::vec2 corners[4] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    // u runs along b and v along t; cross(n, b) = -t, hence handedness -1.
    for (const glm::vec2& c : corners) {
      m.vertices.push_back({0.5f * (n + c.x * b + c.y * t), n, (c + 1.0f) * 0.5f, glm::vec4(b, -1.0f)});
    }
    // The corners run clockwise seen from outside (b x t = -n): the triangles take them in reverse, so that
    // front faces are the outer ones.
    m.indices.insert(m.indices.end(), {base, base + 2, base + 1, base, base + 3, base + 2});
  }
  return m;
}

}  // namespace pbr
