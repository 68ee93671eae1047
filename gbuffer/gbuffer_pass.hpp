#pragma once
#include <vector>

#include "core/frame_block.hpp"
#include "core/gpu_mesh.hpp"
#include "core/scene.hpp"
#include "core/shader_library.hpp"
#include "core/uniform_buffer.hpp"
#include "gbuffer/gbuffer.hpp"

namespace pbr {

// Rasterizes a scene's objects into the G-buffer. Meshes and per-object blocks are uploaded once per scene.
class GBufferPass {
 public:
  GBufferPass(const ShaderLibrary& shaders, const Scene& scene);
  void render(const GBuffer& target, const UniformBuffer<FrameBlock>& frame) const;

 private:
  struct Draw {
    int mesh;
    GLintptr blockOffset;
  };
  Program program_;
  std::vector<GpuMesh> meshes_;
  std::vector<Draw> draws_;
  GLsizeiptr blockStride_;
  Buffer objectBlocks_;
};

}  // namespace pbr
