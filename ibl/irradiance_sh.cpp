#include "ibl/irradiance_sh.hpp"

namespace pbr {

namespace {

// Texels per invocation side, and invocations per workgroup side (shaders/ibl/sh_project.comp).
constexpr GLuint kBlock = 8;
constexpr GLuint kGroupSize = 8;
// Bands 0-2 vary over tens of degrees: faces of 256^2 hold everything they can see (a sun's energy survives the
// box filter of the mip chain), and bound the partial sums to 6 x 32^2 blocks, which sh_reduce.comp adds serially.
constexpr int kMaxProjectedFace = 256;

}  // namespace

IrradianceShPass::IrradianceShPass(const ShaderLibrary& shaders)
    : projectProgram_(shaders.compute("ibl/sh_project.comp")), reduceProgram_(shaders.compute("ibl/sh_reduce.comp")) {}

Buffer IrradianceShPass::run(const Cubemap& environment) const {
  int level = 0;
  while (environment.faceSize(level) > kMaxProjectedFace && level + 1 < environment.levels()) ++level;
  const GLuint blocks = (static_cast<GLuint>(environment.faceSize(level)) + kBlock - 1) / kBlock;
  const GLuint groups = (blocks + kGroupSize - 1) / kGroupSize;
  const Buffer partials("ibl.irradiance.partials", size_t{blocks} * blocks * 6 * 9 * sizeof(glm::vec4), nullptr, 0);
  Buffer coefficients("ibl.irradiance", sizeof(IblBlock), nullptr, 0);

  projectProgram_.use();
  glBindImageTexture(0, environment.id(), level, GL_TRUE, 0, GL_READ_ONLY, GL_RGBA16F);
  partials.bindBase(GL_SHADER_STORAGE_BUFFER, 0);
  glDispatchCompute(groups, groups, 6);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);

  reduceProgram_.use();
  coefficients.bindBase(GL_SHADER_STORAGE_BUFFER, 1);
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_UNIFORM_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  glUseProgram(0);
  checkGlError("IrradianceShPass::run");
  return coefficients;
}

}  // namespace pbr
