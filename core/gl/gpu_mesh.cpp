#include "core/gl/gpu_mesh.hpp"

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
  // The optional streams, one binding each, where the mesh has them.
  if (!data.colors.empty()) {
    colors_.emplace(label + ".colors", data.colors.size() * sizeof(glm::vec4), data.colors.data(), 0);
  }
  if (!data.uv1.empty()) uv1_.emplace(label + ".uv1", data.uv1.size() * sizeof(glm::vec2), data.uv1.data(), 0);
  const struct {
    const std::optional<Buffer>& buffer;
    GLuint location;
    GLint components;
  } streams[] = {{colors_, 4, 4}, {uv1_, 5, 2}};
  for (const auto& s : streams) {
    if (!s.buffer) continue;
    const GLuint binding = s.location - 3;  // 1 and 2, after the interleaved vertices' 0
    glVertexArrayVertexBuffer(vao, binding, s.buffer->id(), 0, static_cast<GLsizei>(s.components * sizeof(float)));
    glEnableVertexArrayAttrib(vao, s.location);
    glVertexArrayAttribFormat(vao, s.location, s.components, GL_FLOAT, GL_FALSE, 0);
    glVertexArrayAttribBinding(vao, s.location, binding);
  }
}

void GpuMesh::draw() const {
  glBindVertexArray(vao_.id());
  glDrawElements(GL_TRIANGLES, indexCount_, GL_UNSIGNED_INT, nullptr);
}

void GpuMesh::drawInstanced(int instances) const {
  glBindVertexArray(vao_.id());
  glDrawElementsInstanced(GL_TRIANGLES, indexCount_, GL_UNSIGNED_INT, nullptr, instances);
}

}  // namespace pbr
