#include "debug/efficiency_debug_pass.hpp"

#include "lighting/lighting_bindings.hpp"

namespace pbr {

void EfficiencyDebugPass::render(const Texture& pairCounts, const UniformBuffer<FrameBlock>& frame,
                                 const UniformBuffer<LegendBlock>& legend, const Texture& ldr) {
  programs_.compute("lighting/efficiency_debug.comp", lightingBindingDefines()).use();
  frame.bind(kFrameUbo.index);
  legend.bind(lighting_binding::kLegendUbo.index);
  glBindImageTexture(lighting_binding::kPairCountImage.index, pairCounts.id(), 0, GL_FALSE, 0, GL_READ_ONLY,
                     GL_RG32UI);
  glBindImageTexture(0, ldr.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA8);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  glDispatchCompute(static_cast<GLuint>((ldr.width() + 7) / 8), static_cast<GLuint>((ldr.height() + 7) / 8), 1);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT |
                  GL_FRAMEBUFFER_BARRIER_BIT);
}

}  // namespace pbr
