#include "lighting/gbuffer_debug_pass.hpp"

#include <string>

#include "core/bindings.hpp"

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

void GBufferDebugPass::render(GBufferChannel channel, const GBuffer& gbuffer, const UniformBuffer<FrameBlock>& frame,
                              const Texture& ldr) {
  const int index = static_cast<int>(channel);
  std::unique_ptr<Program>& program = programs_[static_cast<size_t>(index)];
  if (!program) {
    program = std::make_unique<Program>(
        shaders_.compute("lighting/gbuffer_debug.comp", {{"GBUFFER_CHANNEL", std::to_string(index)}}));
  }
  program->use();
  frame.bind(binding::kFrameUbo);
  glBindTextureUnit(0, gbuffer.baseColor.id());
  glBindTextureUnit(1, gbuffer.normal.id());
  glBindTextureUnit(2, gbuffer.material.id());
  glBindTextureUnit(3, gbuffer.depth.id());
  glBindImageTexture(0, ldr.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA8);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
  glDispatchCompute(static_cast<GLuint>((ldr.width() + 7) / 8), static_cast<GLuint>((ldr.height() + 7) / 8), 1);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT |
                  GL_FRAMEBUFFER_BARRIER_BIT);
}

}  // namespace pbr
