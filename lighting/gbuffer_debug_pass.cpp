#include "lighting/gbuffer_debug_pass.hpp"

#include <stdexcept>
#include <string>

#include "lighting/lighting_bindings.hpp"

namespace pbr {

namespace {

// The named define that selects the channel in lighting/gbuffer_debug.comp; null for the other channels.
const char* channelDefine(DebugChannel channel) {
  switch (channel) {
    case DebugChannel::BaseColor: return "GBUFFER_CHANNEL_BASE_COLOR";
    case DebugChannel::Normal: return "GBUFFER_CHANNEL_NORMAL";
    case DebugChannel::Roughness: return "GBUFFER_CHANNEL_ROUGHNESS";
    case DebugChannel::Metalness: return "GBUFFER_CHANNEL_METALNESS";
    case DebugChannel::Occlusion: return "GBUFFER_CHANNEL_OCCLUSION";
    case DebugChannel::Emission: return "GBUFFER_CHANNEL_EMISSION";
    case DebugChannel::Depth: return "GBUFFER_CHANNEL_DEPTH";
    case DebugChannel::Clusters:
    case DebugChannel::Slices:
    case DebugChannel::Efficiency:
    case DebugChannel::Shadows:
    case DebugChannel::Transparency: return nullptr;
  }
  return nullptr;
}

}  // namespace

bool isGBufferChannel(DebugChannel channel) { return channelDefine(channel) != nullptr; }

ShaderDefines GBufferDebugPass::permutation(DebugChannel channel) {
  const char* define = channelDefine(channel);
  if (!define) throw std::logic_error(std::string("the G-buffer debug pass does not draw ") + toString(channel));
  return {{define, "1"}};
}

void GBufferDebugPass::render(DebugChannel channel, const GBuffer& gbuffer, const UniformBuffer<FrameBlock>& frame,
                              const UniformBuffer<LegendBlock>& legend, const Texture& ldr) {
  programs_.compute("lighting/gbuffer_debug.comp", concat(permutation(channel), lightingBindingDefines())).use();
  frame.bind(kFrameUbo.index);
  legend.bind(lighting_binding::kLegendUbo.index);
  glBindTextureUnit(lighting_binding::kBaseColorUnit.index, gbuffer.baseColor.id());
  glBindTextureUnit(lighting_binding::kNormalUnit.index, gbuffer.normal.id());
  glBindTextureUnit(lighting_binding::kMaterialUnit.index, gbuffer.material.id());
  glBindTextureUnit(lighting_binding::kDepthUnit.index, gbuffer.depth.id());
  glBindImageTexture(0, ldr.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA8);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
  glDispatchCompute(static_cast<GLuint>((ldr.width() + 7) / 8), static_cast<GLuint>((ldr.height() + 7) / 8), 1);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT |
                  GL_FRAMEBUFFER_BARRIER_BIT);
}

}  // namespace pbr
