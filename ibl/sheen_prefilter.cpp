#include "ibl/sheen_prefilter.hpp"

#include <stdexcept>
#include <string>

#include <glm/vec4.hpp>

#include "core/gl/gpu_texture.hpp"
#include "core/gl/uniform_buffer.hpp"

namespace pbr {

namespace {

// Mirrors SheenPrefilterBlock in shaders/ibl/prefilter_sheen.comp.
struct SheenPrefilterBlock {
  glm::ivec4 sizes;  // x: face size of this level, y: samples per texel, z: face size of the environment's level 0
  glm::vec4 params;  // x: sheen roughness of this level
};
static_assert(sizeof(SheenPrefilterBlock) == 32, "std140 layout of SheenPrefilterBlock");

constexpr GLuint kGroupSize = 8;

}  // namespace

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
  UniformBuffer<SheenPrefilterBlock> block("ibl.sheen.block");
  block.bind(0);
  program_.use();
  glBindTextureUnit(0, environment.id());
  glBindSampler(0, 0);  // the cube map's own trilinear filtering
  glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
  for (int level = 0; level < levels; ++level) {
    const int levelSize = prefiltered.faceSize(level);
    const float roughness = levels > 1 ? static_cast<float>(level) / static_cast<float>(levels - 1) : 1.0f;
    block.update({glm::ivec4(levelSize, samples, source, 0), glm::vec4(roughness, 0.0f, 0.0f, 0.0f)});
    glBindImageTexture(0, prefiltered.id(), level, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA16F);
    const GLuint groups = (static_cast<GLuint>(levelSize) + kGroupSize - 1) / kGroupSize;
    glDispatchCompute(groups, groups, 6);
  }
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  glUseProgram(0);
  checkGlError("SheenPrefilterPass::run");
  return prefiltered;
}

}  // namespace pbr
