#include "post/post_pass.hpp"

#include <string>

namespace pbr {

ShaderDefines PostPass::permutation(ToneCurve curve, bool autoExposure) {
  ShaderDefines defines;
  for (const ToneCurve c : kToneCurves) defines.push_back({toneCurveDefine(c), c == curve ? "1" : "0"});
  defines.push_back({"AUTO_EXPOSURE", autoExposure ? "1" : "0"});
  if (autoExposure) defines.push_back({"METER_BINS", std::to_string(kMeterBins)});
  return defines;
}

const Program& PostPass::program(ToneCurve curve, bool autoExposure) {
  const Program*& program = programsByCurve_.at(static_cast<size_t>(curve)).at(autoExposure ? 1 : 0);
  if (!program) {
    program = &programs_.compute("post/post.comp", concat(permutation(curve, autoExposure),
                                                          bindingDefines({kPostUbo, kExposureSsbo})));
  }
  return *program;
}

void PostPass::render(const Texture& hdr, const Texture& ldr, const PostSettings& settings) {
  block_.update({settings.exposure, settings.toneMap ? 1u : 0u,
                 glm::uvec2(static_cast<unsigned>(ldr.width()), static_cast<unsigned>(ldr.height()))});
  program(settings.curve, settings.meter != nullptr).use();
  block_.bind(kPostUbo.index);
  if (settings.meter) settings.meter->bind();
  glBindTextureUnit(0, hdr.id());
  glBindImageTexture(0, ldr.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA8);
  glDispatchCompute(static_cast<GLuint>((ldr.width() + 7) / 8), static_cast<GLuint>((ldr.height() + 7) / 8), 1);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
}

}  // namespace pbr
