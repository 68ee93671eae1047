#include "debug/gbuffer_debug_pass.hpp"

#include <stdexcept>
#include <string>

#include "lighting/lighting_bindings.hpp"

namespace pbr {

ShaderDefines GBufferDebugPass::permutation(DebugChannel channel) {
  const char* define = debugChannelInfo(channel).gbufferDefine;
  if (!define) throw std::logic_error(std::string("the G-buffer debug pass does not draw ") + toString(channel));
  return {{define, "1"}};
}

void GBufferDebugPass::render(DebugChannel channel, const SurfaceTextures& surface,
                              const UniformBuffer<FrameBlock>& frame, const UniformBuffer<LegendBlock>& legend,
                              const Texture& ldr) {
  programs_.compute("lighting/gbuffer_debug.comp", concat(permutation(channel), lightingBindingDefines())).use();
  frame.bind(kFrameUbo.index);
  legend.bind(lighting_binding::kLegendUbo.index);
  glBindTextureUnit(lighting_binding::kBaseColorUnit.index, surface.baseColor.id());
  glBindTextureUnit(lighting_binding::kNormalUnit.index, surface.normal.id());
  glBindTextureUnit(lighting_binding::kMaterialUnit.index, surface.material.id());
  glBindTextureUnit(lighting_binding::kDepthUnit.index, surface.depth.id());
  glBindImageTexture(0, ldr.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA8);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
  glDispatchCompute(static_cast<GLuint>((ldr.width() + 7) / 8), static_cast<GLuint>((ldr.height() + 7) / 8), 1);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT |
                  GL_FRAMEBUFFER_BARRIER_BIT);
}

}  // namespace pbr
