#pragma once

#include "core/gl/program_cache.hpp"
#include "core/gl/shadow_maps.hpp"
#include "core/gl/uniform_buffer.hpp"
#include "core/scene/frame_block.hpp"
#include "debug/debug_legend.hpp"

namespace pbr {

// Replaces the final RGBA8 frame with each pixel's shadow visibility, the light casting lights bring with their
// shadows over what they would bring without (LightingOptions::shadowLight), black where fully shadowed, with the
// shadow atlas inset at the top right: its depth (log scale, the near plane white) and every square outlined in
// its light's colour (`owners`, ShadowPass::ownerMap).
class ShadowDebugPass {
 public:
  explicit ShadowDebugPass(ProgramCache& programs) : programs_(programs) {}
  void render(const Texture& shadowLight, const ShadowMaps& maps, const Texture& owners,
              const UniformBuffer<FrameBlock>& frame, const UniformBuffer<LegendBlock>& legend, const Texture& ldr);

 private:
  ProgramCache& programs_;  // compiled on first use
};

}  // namespace pbr
