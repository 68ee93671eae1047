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

const Texture& SheenAlbedoTable::table() {
  if (!table_) {
    const Program program = shaders_.compute("lighting/sheen_albedo.comp", {});
    table_.emplace(computeSquareTable("lighting.sheenAlbedo", program, GL_R32F, kSize, kSamples));
  }
  return *table_;
}

}  // namespace pbr
