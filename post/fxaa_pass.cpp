#include "post/fxaa_pass.hpp"

#include "post/post_bindings.hpp"

namespace pbr {

ShaderDefines FxaaPass::defines(bool edgePixels) {
  return concat({{"FXAA_EDGE_PIXELS", edgePixels ? "1" : "0"}}, bindingDefines({kFxaaEdgesSsbo}));
}

FxaaPass::FxaaPass(ProgramCache& programs)
    : programs_(programs),
      bilinear_("fxaa.sampler", GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE, GL_LINEAR, GL_LINEAR) {}

void FxaaPass::render(const Texture& display, const Texture& out) {
  const size_t bytes = sizeof(FxaaEdgesHeader) + sizeof(uint32_t) * size_t(out.width()) * size_t(out.height());
  if (!edges_ || edges_->size() < bytes) edges_ = std::make_unique<Buffer>("fxaa.edges", bytes);
  const FxaaEdgesHeader none{{0, 1, 1}, 0};
  edges_->upload(&none, sizeof none);
  edges_->bindBase(GL_SHADER_STORAGE_BUFFER, kFxaaEdgesSsbo.index);
  glBindTextureUnit(0, display.id());
  glBindSampler(0, bilinear_.id());
  glBindImageTexture(0, out.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA8);
  programs_.compute("post/fxaa.comp", defines(false)).use();
  glDispatchCompute(static_cast<GLuint>((out.width() + 7) / 8), static_cast<GLuint>((out.height() + 7) / 8), 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
  programs_.compute("post/fxaa.comp", defines(true)).use();
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, edges_->id());
  glDispatchComputeIndirect(0);
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
  glBindSampler(0, 0);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
}

}  // namespace pbr
