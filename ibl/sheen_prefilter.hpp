#pragma once
#include "core/gl/shader_library.hpp"
#include "ibl/cubemap.hpp"

namespace pbr {

// KHR_materials_sheen's prefiltered cube map (shaders/ibl/prefilter_sheen.comp): level k holds the environment
// weighted by the "Charlie" lobe of sheen roughness k / (levels - 1) (clamped as the lobe is, to 0.07), at
// `faceSize` halved k times. Made only for scenes whose materials have a sheen.
class SheenPrefilterPass {
 public:
  explicit SheenPrefilterPass(const ShaderLibrary& shaders);
  // `environment` needs its full mip chain: samples read the level that matches their solid angle.
  Cubemap run(const Cubemap& environment, int faceSize, int levels, int samples) const;

 private:
  Program program_;
};

}  // namespace pbr
