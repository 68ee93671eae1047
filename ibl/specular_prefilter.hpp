#pragma once
#include "core/gl/shader_library.hpp"
#include "ibl/cubemap.hpp"

namespace pbr {

// The GGX-prefiltered specular cube map (shaders/ibl/prefilter_specular.comp): level k holds the environment
// convolved with the GGX lobe of perceptual roughness k / (levels - 1), at the environment's face size halved k
// times; level 0 (roughness 0, a mirror) is a copy of the environment's level 0.
class SpecularPrefilterPass {
 public:
  explicit SpecularPrefilterPass(const ShaderLibrary& shaders);
  // `environment` needs its full mip chain: samples read the level that matches their share of the lobe.
  Cubemap run(const Cubemap& environment, int levels, int samples) const;

 private:
  Program program_;
};

}  // namespace pbr
