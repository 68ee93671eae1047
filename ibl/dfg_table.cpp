#include "ibl/dfg_table.hpp"

#include <stdexcept>

#include <glm/vec4.hpp>

#include "core/uniform_buffer.hpp"

namespace pbr {

namespace {

// Mirrors DfgPassBlock in shaders/ibl/dfg.comp.
struct DfgPassBlock {
  glm::ivec4 sizes;  // x: table size, y: samples per texel
};
static_assert(sizeof(DfgPassBlock) == 16, "std140 layout of DfgPassBlock");

constexpr GLuint kGroupSize = 8;

}  // namespace

DfgTablePass::DfgTablePass(const ShaderLibrary& shaders) : program_(shaders.compute("ibl/dfg.comp")) {}

Texture DfgTablePass::run(int size, int samples) const {
  if (size < 2) throw std::invalid_argument("DFG table size must be >= 2");
  if (samples < 1) throw std::invalid_argument("DFG samples must be >= 1");
  Texture table(GL_RG16F, size, size);
  const UniformBuffer<DfgPassBlock> block({glm::ivec4(size, samples, 0, 0)});
  block.bind(0);
  program_.use();
  glBindImageTexture(0, table.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RG16F);
  const GLuint groups = (static_cast<GLuint>(size) + kGroupSize - 1) / kGroupSize;
  glDispatchCompute(groups, groups, 1);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
  glUseProgram(0);
  checkGlError("DfgTablePass::run");
  return table;
}

}  // namespace pbr
