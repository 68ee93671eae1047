#pragma once
#include <map>
#include <optional>
#include <string>

#include "core/gl/shader_library.hpp"

namespace pbr {

// Tables of the directional albedo of each PBR variant's BRDF (shaders/lighting/ambient_albedo.comp), with which
// the lighting pass reflects uniform ambient light exactly as the BRDF would rather than by a closed-form guess.
// One RGBA32F table of kSize x kSize per variant, made on first use and kept.
class AmbientAlbedoTables {
 public:
  static constexpr int kSize = 64;
  static constexpr int kSamples = 2048;  // per texel: known to about 1e-3 of the albedo

  explicit AmbientAlbedoTables(const ShaderLibrary& shaders) : shaders_(shaders) {}
  // The table for the variant whose brdf.glsl defines these are.
  const Texture& table(const ShaderDefines& variantDefines);

 private:
  const ShaderLibrary& shaders_;
  std::map<std::string, Texture> tables_;  // by their defines
};

// E(n.v, r), the directional albedo of KHR_materials_sheen's white fibre lobe (shaders/lighting/sheen_albedo.comp):
// the sheen's albedo scaling of the base and its own reflection of ambient light. One R32F table, made on first use.
class SheenAlbedoTable {
 public:
  static constexpr int kSize = 32;
  static constexpr int kSamples = 1024;  // per texel, cosine-weighted: the lobe is broad

  explicit SheenAlbedoTable(const ShaderLibrary& shaders) : shaders_(shaders) {}
  const Texture& table();

 private:
  const ShaderLibrary& shaders_;
  std::optional<Texture> table_;
};

}  // namespace pbr
