#include "lighting/ambient_albedo.hpp"

#include <glm/vec4.hpp>

#include "core/uniform_buffer.hpp"

namespace pbr {

namespace {

// Mirrors AmbientAlbedoBlock in shaders/lighting/ambient_albedo.comp.
struct AmbientAlbedoBlock {
  glm::ivec4 sizes;  // x: table size, y: samples per texel
};
static_assert(sizeof(AmbientAlbedoBlock) == 16, "std140 layout of AmbientAlbedoBlock");

constexpr GLuint kGroupSize = 8;

}  // namespace

const Texture& AmbientAlbedoTables::table(const ShaderDefines& variantDefines) {
  const std::string key = definesKey(variantDefines);
  auto it = tables_.find(key);
  if (it != tables_.end()) return it->second;
  const Program program = shaders_.compute("lighting/ambient_albedo.comp", variantDefines);
  Texture table(GL_RGBA32F, kSize, kSize);
  const UniformBuffer<AmbientAlbedoBlock> block({glm::ivec4(kSize, kSamples, 0, 0)});
  block.bind(0);
  program.use();
  glBindImageTexture(0, table.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  const GLuint groups = (static_cast<GLuint>(kSize) + kGroupSize - 1) / kGroupSize;
  glDispatchCompute(groups, groups, 1);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
  glUseProgram(0);
  checkGlError("AmbientAlbedoTables::table");
  return tables_.emplace(key, std::move(table)).first->second;
}

}  // namespace pbr
