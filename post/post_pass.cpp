#include "post/post_pass.hpp"

namespace pbr {

ShaderDefines PostPass::permutation(ToneCurve curve) {
  ShaderDefines defines;
  for (const ToneCurve c : kToneCurves) defines.push_back({toneCurveDefine(c), c == curve ? "1" : "0"});
  return defines;
}

const Program& PostPass::program(ToneCurve curve) {
  const Program*& program = byCurve_.at(static_cast<size_t>(curve));
  if (!program) program = &programs_.compute("post/post.comp", concat(permutation(curve), bindingDefines({kPostUbo})));
  return *program;
}

void PostPass::render(const Texture& hdr, const Texture& ldr, const PostSettings& settings) {
  block_.update({settings.exposure, settings.toneMap ? 1u : 0u,
                 glm::uvec2(static_cast<unsigned>(ldr.width()), static_cast<unsigned>(ldr.height()))});
  program(settings.curve).use();
  block_.bind(kPostUbo.index);
  glBindTextureUnit(0, hdr.id());
  glBindImageTexture(0, ldr.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA8);
  glDispatchCompute(static_cast<GLuint>((ldr.width() + 7) / 8), static_cast<GLuint>((ldr.height() + 7) / 8), 1);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
}

}  // namespace pbr
