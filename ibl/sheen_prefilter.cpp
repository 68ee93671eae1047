#include "ibl/sheen_prefilter.hpp"

#include <stdexcept>
#include <string>

#include "core/gl/gpu_texture.hpp"
#include "ibl/prefilter_levels.hpp"

namespace pbr {

SheenPrefilterPass::SheenPrefilterPass(const ShaderLibrary& shaders)
    : program_(shaders.compute("ibl/prefilter_sheen.comp")) {}

Cubemap SheenPrefilterPass::run(const Cubemap& environment, int faceSize, int levels, int samples) const {
  if (faceSize < 1 || levels < 1 || levels > mipLevelCount(faceSize, faceSize)) {
    throw std::invalid_argument("sheen levels must be in [1, " + std::to_string(mipLevelCount(faceSize, faceSize)) +
                                "] for a face size of " + std::to_string(faceSize));
  }
  const int source = environment.faceSize();
  if (environment.levels() != mipLevelCount(source, source)) {
    throw std::invalid_argument("the environment cube map needs its full mip chain");
  }
  if (samples < 1) throw std::invalid_argument("sheen samples must be >= 1");
  Cubemap prefiltered("ibl.sheen", GL_RGBA16F, faceSize, levels);
  prefilterLevels(program_, environment, prefiltered, 0, samples);
  checkGlError("SheenPrefilterPass::run");
  return prefiltered;
}

}  // namespace pbr
