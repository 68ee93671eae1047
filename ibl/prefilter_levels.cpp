#include "ibl/prefilter_levels.hpp"

#include <glm/vec4.hpp>

#include "core/gl/gpu_texture.hpp"
#include "core/gl/uniform_buffer.hpp"

namespace pbr {

namespace {

// Mirrors the PrefilterPassBlock of shaders/ibl/prefilter_specular.comp and prefilter_sheen.comp.
struct PrefilterPassBlock {
  glm::ivec4 sizes;  // x: face size of this level, y: samples per texel, z: face size of the environment's level 0
  glm::vec4 params;  // x: roughness of this level
};
static_assert(sizeof(PrefilterPassBlock) == 32, "std140 layout of PrefilterPassBlock");

constexpr GLuint kGroupSize = 8;

}  // namespace

void prefilterLevels(const Program& program, const Cubemap& environment, const Cubemap& target, int first,
                     int samples) {
  const int levels = target.levels();
  UniformBuffer<PrefilterPassBlock> block("ibl.prefilter.block");
  block.bind(0);
  program.use();
  glBindTextureUnit(0, environment.id());
  glBindSampler(0, 0);  // the cube map's own trilinear filtering
  glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
  for (int level = first; level < levels; ++level) {
    const int levelSize = target.faceSize(level);
    const float roughness = levels > 1 ? static_cast<float>(level) / static_cast<float>(levels - 1) : 1.0f;
    block.update({glm::ivec4(levelSize, samples, environment.faceSize(), 0), glm::vec4(roughness, 0.0f, 0.0f, 0.0f)});
    glBindImageTexture(0, target.id(), level, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA16F);
    const GLuint groups = (static_cast<GLuint>(levelSize) + kGroupSize - 1) / kGroupSize;
    glDispatchCompute(groups, groups, 6);
  }
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  glUseProgram(0);
}

}  // namespace pbr
