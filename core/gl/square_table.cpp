#include "core/gl/square_table.hpp"

#include <stdexcept>

#include <glm/vec4.hpp>

#include "core/gl/debug_group.hpp"
#include "core/gl/uniform_buffer.hpp"

namespace pbr {

namespace {

// Mirrors the `sizes` block of the table programs.
struct TableBlock {
  glm::ivec4 sizes;  // x: table size, y: samples per texel
};
static_assert(sizeof(TableBlock) == 16, "std140 layout of the table block");

constexpr GLuint kGroupSize = 8;

}  // namespace

Texture computeSquareTable(const std::string& label, const Program& program, GLenum format, int size, int samples) {
  if (size < 2) throw std::invalid_argument("table size must be >= 2");
  if (samples < 1) throw std::invalid_argument("table samples must be >= 1");
  const DebugGroup group(label);
  Texture table(label, format, size, size);
  const UniformBuffer<TableBlock> block(label + ".sizes", {glm::ivec4(size, samples, 0, 0)});
  block.bind(0);
  program.use();
  glBindImageTexture(0, table.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, format);
  const GLuint groups = (static_cast<GLuint>(size) + kGroupSize - 1) / kGroupSize;
  glDispatchCompute(groups, groups, 1);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
  glUseProgram(0);
  checkGlError("computing a lookup table");
  return table;
}

}  // namespace pbr
