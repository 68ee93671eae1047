#include "lighting/ambient_albedo.hpp"

#include "core/gl/square_table.hpp"

namespace pbr {

const Texture& AmbientAlbedoTables::table(const ShaderDefines& variantDefines) {
  const std::string key = definesKey(variantDefines);
  auto it = tables_.find(key);
  if (it != tables_.end()) return it->second;
  const Program program = shaders_.compute("lighting/ambient_albedo.comp", variantDefines);
  const std::string label = programLabel("lighting.ambientAlbedo", variantDefines);
  return tables_.emplace(key, computeSquareTable(label, program, GL_RGBA32F, kSize, kSamples)).first->second;
}

}  // namespace pbr
