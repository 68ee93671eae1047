#include "ibl/specular_prefilter.hpp"

#include <stdexcept>
#include <string>

#include "core/gl/gpu_texture.hpp"
#include "ibl/prefilter_levels.hpp"

namespace pbr {

SpecularPrefilterPass::SpecularPrefilterPass(const ShaderLibrary& shaders)
    : program_(shaders.compute("ibl/prefilter_specular.comp")) {}

Cubemap SpecularPrefilterPass::run(const Cubemap& environment, int levels, int samples) const {
  const int size = environment.faceSize();
  if (levels < 1 || levels > mipLevelCount(size, size)) {
    throw std::invalid_argument("specular levels must be in [1, " + std::to_string(mipLevelCount(size, size)) + "]");
  }
  if (environment.levels() != mipLevelCount(size, size)) {
    throw std::invalid_argument("the environment cube map needs its full mip chain");
  }
  if (samples < 1) throw std::invalid_argument("specular samples must be >= 1");
  Cubemap prefiltered("ibl.specular", GL_RGBA16F, size, levels);
  glCopyImageSubData(environment.id(), GL_TEXTURE_CUBE_MAP, 0, 0, 0, 0, prefiltered.id(), GL_TEXTURE_CUBE_MAP, 0, 0,
                     0, 0, size, size, 6);
  prefilterLevels(program_, environment, prefiltered, 1, samples);
  checkGlError("SpecularPrefilterPass::run");
  return prefiltered;
}

}  // namespace pbr
