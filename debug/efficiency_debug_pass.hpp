#pragma once

#include "core/gl/program_cache.hpp"
#include "core/gl/uniform_buffer.hpp"
#include "core/scene/frame_block.hpp"
#include "debug/debug_legend.hpp"

namespace pbr {

// Replaces the final RGBA8 frame with each pixel's culling efficiency, contributing over evaluated light-pixel
// pairs as the lighting pass counted them (LightingOptions::pairCounts), as a heat map with its legend.
class EfficiencyDebugPass {
 public:
  explicit EfficiencyDebugPass(ProgramCache& programs) : programs_(programs) {}
  void render(const Texture& pairCounts, const UniformBuffer<FrameBlock>& frame,
              const UniformBuffer<LegendBlock>& legend, const Texture& ldr);

 private:
  ProgramCache& programs_;  // compiled on first use
};

}  // namespace pbr
