#include "core/gpu_mesh.hpp"

#include <atomic>
#include <cstddef>

namespace pbr {

namespace {
std::atomic<size_t> meshUploads{0};
}  // namespace

size_t gpuMeshUploads() { return meshUploads.load(); }

GpuMesh::GpuMesh(const MeshData& data, const std::string& label)
    : vertices_(label + ".vertices", data.vertices.size() * sizeof(Vertex), data.vertices.data(), 0),
      indices_(label + ".indices", data.indices.size() * sizeof(uint32_t), data.indices.data(), 0),
      vao_(label),
      indexCount_(static_cast<GLsizei>(data.indices.size())) {
  ++meshUploads;
  const GLuint vao = vao_.id();
  glVertexArrayVertexBuffer(vao, 0, vertices_.id(), 0, sizeof(Vertex));
  glVertexArrayElementBuffer(vao, indices_.id());
  const struct {
    GLuint location;
    GLint components;
    size_t offset;
  } attributes[] = {{0, 3, offsetof(Vertex, position)},
                    {1, 3, offsetof(Vertex, normal)},
                    {2, 2, offsetof(Vertex, uv)},
                    {3, 4, offsetof(Vertex, tangent)}};
  for (const auto& a : attributes) {
    glEnableVertexArrayAttrib(vao, a.location);
    glVertexArrayAttribFormat(vao, a.location, a.components, GL_FLOAT, GL_FALSE, static_cast<GLuint>(a.offset));
    glVertexArrayAttribBinding(vao, a.location, 0);
  }
}

void GpuMesh::draw() const {
  glBindVertexArray(vao_.id());
  glDrawElements(GL_TRIANGLES, indexCount_, GL_UNSIGNED_INT, nullptr);
}

}  // namespace pbr
