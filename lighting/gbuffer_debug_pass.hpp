#pragma once

#include "core/frame_block.hpp"
#include "core/program_cache.hpp"
#include "core/uniform_buffer.hpp"
#include "gbuffer/gbuffer.hpp"

namespace pbr {

enum class GBufferChannel { BaseColor, Normal, Roughness, Metalness, Depth };
const char* toString(GBufferChannel channel);

// Replaces the final RGBA8 frame with a picture of one G-buffer channel, decoded as the lighting pass reads it.
class GBufferDebugPass {
 public:
  explicit GBufferDebugPass(ProgramCache& programs) : programs_(programs) {}
  void render(GBufferChannel channel, const GBuffer& gbuffer, const UniformBuffer<FrameBlock>& frame,
              const Texture& ldr);

 private:
  ProgramCache& programs_;  // each channel compiled on first use
};

}  // namespace pbr
