#pragma once
#include <cstddef>
#include <optional>

#include "core/gl/environment_maps.hpp"
#include "core/gl/profiler.hpp"
#include "core/gl/shader_library.hpp"
#include "ibl/cubemap.hpp"
#include "ibl/environment.hpp"

namespace pbr {

struct IblSettings {
  int faceSize = 128;         // environment and prefiltered specular cube faces at level 0
  int specularLevels = 6;     // roughness k / (levels - 1) at level k; 128 -> 4x4 faces at roughness 1
  int specularSamples = 256;  // GGX samples per prefiltered texel
  int dfgSize = 64;           // DFG table, dfgSize^2 texels
  int dfgSamples = 512;       // GGX samples per DFG texel
  // KHR_materials_sheen's Charlie-prefiltered cube map, made only for scenes whose materials have a sheen: its
  // faces at level 0 (the lobe is broad, a small map holds it), its levels (sheen roughness k / (levels - 1)),
  // its samples per texel.
  bool sheen = false;
  int sheenFaceSize = 32;
  int sheenLevels = 6;
  int sheenSamples = 4096;
};

// Everything the lighting pass needs for image-based lighting of one environment, precomputed on the GPU once:
// diffuse as 9 spherical-harmonic coefficients (a uniform block), specular as a GGX-prefiltered cube map, the
// split-sum DFG table, and for scenes with a sheen the Charlie-prefiltered cube map. Shaders sample them through
// shaders/ibl/ibl_sample.glsl.
class IblMaps {
 public:
  // With a profiler, the precomputation is one profiler frame of its own, passes "ibl environment",
  // "ibl irradiance", "ibl specular" and "ibl dfg", compiled beforehand (llvmpipe still generates a shader's
  // machine code at its first dispatch, inside the pass): call it outside a frame.
  // Throws std::invalid_argument for settings out of range.
  IblMaps(const ShaderLibrary& shaders, const Environment& environment, const IblSettings& settings = {},
          Profiler* profiler = nullptr);

  // The maps as the lighting pass and other readers take them (bindEnvironmentMaps).
  EnvironmentMaps maps() const;
  // GPU memory the maps hold.
  size_t bytes() const;

  const IblSettings& settings() const { return settings_; }
  const Buffer& irradiance() const { return irradiance_; }  // one IblBlock
  const Cubemap& specular() const { return specular_; }
  const Texture& dfg() const { return dfg_; }
  const Cubemap* sheen() const { return sheen_ ? &*sheen_ : nullptr; }

 private:
  struct Maps;
  static Maps precompute(const ShaderLibrary& shaders, const Environment& environment, const IblSettings& settings,
                         Profiler* profiler);
  IblMaps(Maps&& maps, const IblSettings& settings);

  IblSettings settings_;
  Buffer irradiance_;
  Cubemap specular_;
  Texture dfg_;
  std::optional<Cubemap> sheen_;
  Sampler specularSampler_;
  Sampler dfgSampler_;
};

}  // namespace pbr
