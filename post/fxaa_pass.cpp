#include "post/fxaa_pass.hpp"

namespace pbr {

FxaaPass::FxaaPass(ProgramCache& programs)
    : programs_(programs),
      bilinear_("fxaa.sampler", GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE, GL_LINEAR, GL_LINEAR) {}

void FxaaPass::render(const Texture& display, const Texture& out) {
  programs_.compute("post/fxaa.comp").use();
  glBindTextureUnit(0, display.id());
  glBindSampler(0, bilinear_.id());
  glBindImageTexture(0, out.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA8);
  glDispatchCompute(static_cast<GLuint>((out.width() + 7) / 8), static_cast<GLuint>((out.height() + 7) / 8), 1);
  glBindSampler(0, 0);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
}

}  // namespace pbr
