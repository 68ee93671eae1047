#pragma once
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace pbr {

struct Vertex {
  glm::vec3 position;
  glm::vec3 normal;
  glm::vec2 uv;
  glm::vec4 tangent;  // xyz along +u, w = handedness: bitangent = cross(normal, tangent.xyz) * w (glTF convention)
};

struct MeshData {
  std::vector<Vertex> vertices;
  std::vector<uint32_t> indices;  // triangle list, counter-clockwise front faces
  // Optional vertex streams, one element per vertex where present, empty where the mesh has none (and then
  // neither uploaded nor read by the shaders): glTF's COLOR_0 (linear RGBA, multiplying the base colour and its
  // alpha) and TEXCOORD_1 (the second UV set, for maps whose texCoord is 1).
  std::vector<glm::vec4> colors;
  std::vector<glm::vec2> uv1;
};

// Each shape fits the unit cube centred at the origin.
MeshData makePlaneMesh();                      // the square y = 0, x and z in [-0.5, 0.5], normal +Y
MeshData makeSphereMesh(int segments = 64, int rings = 32);  // radius 0.5
// How far inside a sphere of `radius` its tessellation into `segments` around and segments / 2 rings lies at most:
// a facet spanning 2 pi / segments both ways has its centre radius (1 - cos^2(pi / segments)) in.
float sphereTessellationDepth(float radius, int segments);
MeshData makeBoxMesh();                        // the unit cube, flat normals per face

}  // namespace pbr
