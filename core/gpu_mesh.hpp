#pragma once
#include <cstddef>
#include <string>

#include "core/gl_objects.hpp"
#include "core/mesh.hpp"

namespace pbr {

// A mesh uploaded once: interleaved Vertex buffer (locations 0 position, 1 normal, 2 uv, 3 tangent) and 32-bit indices.
// Meshes uploaded by this process so far: how tests check that a resize uploads no scene data again.
size_t gpuMeshUploads();

class GpuMesh {
 public:
  // `label` names its buffers and vertex array ("mesh 3" -> "mesh 3.vertices", ...).
  GpuMesh(const MeshData& data, const std::string& label);
  void draw() const;

 private:
  Buffer vertices_;
  Buffer indices_;
  VertexArray vao_;
  GLsizei indexCount_;
};

}  // namespace pbr
