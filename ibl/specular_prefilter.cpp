#include "ibl/specular_prefilter.hpp"

#include <stdexcept>
#include <string>

#include <glm/vec4.hpp>

#include "core/gl/gpu_texture.hpp"
#include "core/gl/uniform_buffer.hpp"

namespace pbr {

namespace {

// Mirrors PrefilterPassBlock in shaders/ibl/prefilter_specular.comp.
struct PrefilterPassBlock {
  glm::ivec4 sizes;  // x: face size of this level, y: samples per texel, z: face size of the environment's level 0
  glm::vec4 params;  // x: perceptual roughness of this level
};
static_assert(sizeof(PrefilterPassBlock) == 32, "std140 layout of PrefilterPassBlock");

constexpr GLuint kGroupSize = 8;

}  // namespace

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

  UniformBuffer<PrefilterPassBlock> block("ibl.specular.block");
  block.bind(0);
  program_.use();
  glBindTextureUnit(0, environment.id());
  glBindSampler(0, 0);  // the cube map's own trilinear filtering
  glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
  for (int level = 1; level < levels; ++level) {
    const int levelSize = prefiltered.faceSize(level);
    block.update({glm::ivec4(levelSize, samples, size, 0),
                  glm::vec4(static_cast<float>(level) / static_cast<float>(levels - 1), 0.0f, 0.0f, 0.0f)});
    glBindImageTexture(0, prefiltered.id(), level, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA16F);
    const GLuint groups = (static_cast<GLuint>(levelSize) + kGroupSize - 1) / kGroupSize;
    glDispatchCompute(groups, groups, 6);
  }
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  glUseProgram(0);
  checkGlError("SpecularPrefilterPass::run");
  return prefiltered;
}

}  // namespace pbr
