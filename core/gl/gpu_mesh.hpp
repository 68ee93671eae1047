#pragma once
#include <cstddef>
#include <optional>
#include <string>

#include "core/gl/gl_objects.hpp"
#include "core/scene/mesh.hpp"

namespace pbr {

// A mesh uploaded once: interleaved Vertex buffer (locations 0 position, 1 normal, 2 uv, 3 tangent) and 32-bit
// indices, and the optional streams where the mesh has them, each a buffer of its own: colours at location 4 and
// the second UV set at location 5 (the G-buffer's VERTEX_COLORS and UV1 permutations read them).
// Meshes uploaded by this process so far: how tests check that a resize uploads no scene data again.
size_t gpuMeshUploads();

class GpuMesh {
 public:
  // `label` names its buffers and vertex array ("mesh 3" -> "mesh 3.vertices", ...).
  GpuMesh(const MeshData& data, const std::string& label);
  void draw() const;
  // `instances` copies at once (gl_InstanceID 0 to instances - 1).
  void drawInstanced(int instances) const;

 private:
  Buffer vertices_;
  Buffer indices_;
  std::optional<Buffer> colors_;  // none without colours
  std::optional<Buffer> uv1_;     // none without a second UV set
  VertexArray vao_;
  GLsizei indexCount_;
};

}  // namespace pbr
