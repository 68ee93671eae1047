#pragma once

#include "core/gl/program_cache.hpp"
#include "core/gl/uniform_buffer.hpp"
#include "core/scene/frame_block.hpp"
#include "debug/debug_channel.hpp"
#include "debug/debug_legend.hpp"
#include "lighting/lighting_pass.hpp"

namespace pbr {

// Replaces the final RGBA8 frame with a picture of one G-buffer channel, decoded as the lighting pass reads it, and
// its legend. Emission is the exception: the frame is what post made of the emitted radiance alone, kept, and the
// legend is drawn over it.
class GBufferDebugPass {
 public:
  explicit GBufferDebugPass(ProgramCache& programs) : programs_(programs) {}
  // Throws std::logic_error for a channel that is not a surface channel.
  // `surface` as the lighting pass reads it.
  void render(DebugChannel channel, const SurfaceTextures& surface, const UniformBuffer<FrameBlock>& frame,
              const UniformBuffer<LegendBlock>& legend, const Texture& ldr);
  // The defines of lighting/gbuffer_debug.comp for the channel.
  static ShaderDefines permutation(DebugChannel channel);

 private:
  ProgramCache& programs_;  // each channel compiled on first use
};

}  // namespace pbr
