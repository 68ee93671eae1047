#include "debug/shadow_debug_pass.hpp"

#include "lighting/lighting_bindings.hpp"

namespace pbr {

void ShadowDebugPass::render(const Texture& shadowLight, const ShadowMaps& maps, const Texture& owners,
                             const UniformBuffer<FrameBlock>& frame, const UniformBuffer<LegendBlock>& legend,
                             const Texture& ldr) {
  using namespace lighting_binding;
  programs_.compute("lighting/shadow_debug.comp", lightingBindingDefines()).use();
  frame.bind(kFrameUbo.index);
  legend.bind(kLegendUbo.index);
  glBindImageTexture(kShadowLightImage.index, shadowLight.id(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_RG32F);
  // The atlas's depth itself, without the lighting pass's comparison sampler.
  glBindTextureUnit(kShadowDepthUnit.index, maps.atlas);
  glBindSampler(kShadowDepthUnit.index, 0);
  glBindTextureUnit(kShadowOwnerUnit.index, owners.id());
  glBindSampler(kShadowOwnerUnit.index, 0);
  glBindImageTexture(0, ldr.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA8);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
  glDispatchCompute(static_cast<GLuint>((ldr.width() + 7) / 8), static_cast<GLuint>((ldr.height() + 7) / 8), 1);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT |
                  GL_FRAMEBUFFER_BARRIER_BIT);
}

}  // namespace pbr
