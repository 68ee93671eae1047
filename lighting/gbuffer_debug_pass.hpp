#pragma once

#include "core/frame_block.hpp"
#include "core/program_cache.hpp"
#include "core/uniform_buffer.hpp"
#include "gbuffer/gbuffer.hpp"
#include "lighting/debug_channel.hpp"
#include "lighting/debug_legend.hpp"

namespace pbr {

// Whether GBufferDebugPass draws the channel: the surface's channels and the emission the geometry pass writes.
bool isGBufferChannel(DebugChannel channel);

// Replaces the final RGBA8 frame with a picture of one G-buffer channel, decoded as the lighting pass reads it, and
// its legend. Emission is the exception: the frame is what post made of the emitted radiance alone, kept, and the
// legend is drawn over it.
class GBufferDebugPass {
 public:
  explicit GBufferDebugPass(ProgramCache& programs) : programs_(programs) {}
  // Throws std::logic_error for a channel that is not a surface channel.
  void render(DebugChannel channel, const GBuffer& gbuffer, const UniformBuffer<FrameBlock>& frame,
              const UniformBuffer<LegendBlock>& legend, const Texture& ldr);
  // The defines of lighting/gbuffer_debug.comp for the channel.
  static ShaderDefines permutation(DebugChannel channel);

 private:
  ProgramCache& programs_;  // each channel compiled on first use
};

}  // namespace pbr
