#pragma once

#include "core/gl/blended_surfaces.hpp"
#include "core/gl/program_cache.hpp"
#include "core/gl/uniform_buffer.hpp"
#include "core/scene/frame_block.hpp"
#include "debug/debug_legend.hpp"

namespace pbr {

// Layer counts from 0 to this many (and more) span the heat ramp of the transparency debug view.
constexpr int kMaxShownLayers = 8;

// Replaces the final RGBA8 frame with the number of BLEND layers each pixel shows in front of its opaque surface:
// the BLEND surfaces' fragments, depth-tested against the G-buffer as the transparency pass draws them, counted into
// `layers` (R32F, the frame's size, added to by each fragment), then shown on the heat ramp with its legend.
class TransparencyDebugPass {
 public:
  explicit TransparencyDebugPass(ProgramCache& programs) : programs_(programs) {}
  // `surfaces` draws into the framebuffer holding `layers` over the G-buffer's depth.
  void render(const BlendedSurfaces& surfaces, const Texture& layers, const UniformBuffer<FrameBlock>& frame,
              const UniformBuffer<LegendBlock>& legend, const Texture& ldr);

 private:
  ProgramCache& programs_;  // compiled on first use
};

}  // namespace pbr
