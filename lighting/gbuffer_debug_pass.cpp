#include "lighting/gbuffer_debug_pass.hpp"

#include <string>

#include "lighting/lighting_bindings.hpp"

namespace pbr {

const char* toString(GBufferChannel channel) {
  switch (channel) {
    case GBufferChannel::BaseColor: return "baseColor";
    case GBufferChannel::Normal: return "normals";
    case GBufferChannel::Roughness: return "roughness";
    case GBufferChannel::Metalness: return "metalness";
    case GBufferChannel::Depth: return "depth";
  }
  return "?";
}

// The named define that selects the channel in lighting/gbuffer_debug.comp.
const char* channelDefine(GBufferChannel channel) {
  switch (channel) {
    case GBufferChannel::BaseColor: return "GBUFFER_CHANNEL_BASE_COLOR";
    case GBufferChannel::Normal: return "GBUFFER_CHANNEL_NORMAL";
    case GBufferChannel::Roughness: return "GBUFFER_CHANNEL_ROUGHNESS";
    case GBufferChannel::Metalness: return "GBUFFER_CHANNEL_METALNESS";
    case GBufferChannel::Depth: return "GBUFFER_CHANNEL_DEPTH";
  }
  return "GBUFFER_CHANNEL_DEPTH";
}

void GBufferDebugPass::render(GBufferChannel channel, const GBuffer& gbuffer, const UniformBuffer<FrameBlock>& frame,
                              const Texture& ldr) {
  programs_.compute("lighting/gbuffer_debug.comp", concat({{channelDefine(channel), "1"}}, lightingBindingDefines())).use();
  frame.bind(kFrameUbo.index);
  glBindTextureUnit(lighting_binding::kBaseColorUnit.index, gbuffer.baseColor.id());
  glBindTextureUnit(lighting_binding::kNormalUnit.index, gbuffer.normal.id());
  glBindTextureUnit(lighting_binding::kMaterialUnit.index, gbuffer.material.id());
  glBindTextureUnit(lighting_binding::kDepthUnit.index, gbuffer.depth.id());
  glBindImageTexture(0, ldr.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA8);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
  glDispatchCompute(static_cast<GLuint>((ldr.width() + 7) / 8), static_cast<GLuint>((ldr.height() + 7) / 8), 1);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT |
                  GL_FRAMEBUFFER_BARRIER_BIT);
}

}  // namespace pbr
