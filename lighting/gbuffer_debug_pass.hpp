#pragma once
#include <array>
#include <memory>

#include "core/frame_block.hpp"
#include "core/shader_library.hpp"
#include "core/uniform_buffer.hpp"
#include "gbuffer/gbuffer.hpp"

namespace pbr {

enum class GBufferChannel { BaseColor, Normal, Roughness, Metalness, Depth };
const char* toString(GBufferChannel channel);

// Replaces the final RGBA8 frame with a picture of one G-buffer channel, decoded as the lighting pass reads it.
class GBufferDebugPass {
 public:
  explicit GBufferDebugPass(const ShaderLibrary& shaders) : shaders_(shaders) {}
  void render(GBufferChannel channel, const GBuffer& gbuffer, const UniformBuffer<FrameBlock>& frame,
              const Texture& ldr);

 private:
  const ShaderLibrary& shaders_;
  std::array<std::unique_ptr<Program>, 5> programs_;  // compiled on first use, one per channel
};

}  // namespace pbr
