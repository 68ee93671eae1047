#pragma once
#include "core/gl/shader_library.hpp"
#include "ibl/cubemap.hpp"
#include "ibl/environment.hpp"

namespace pbr {

// Renders an Environment into an RGBA16F cube map with its full mip chain (shaders/ibl/environment_cubemap.comp):
// the source of every IBL map. Radiance above the half-float range is clamped to it.
class EnvironmentCubemapPass {
 public:
  explicit EnvironmentCubemapPass(const ShaderLibrary& shaders);

  // A sun smaller than a texel is widened to one texel (at the face centre) at the radiance that keeps its
  // energy, so that it neither vanishes between subsamples nor ends up in one: what lighting needs of a sun is its
  // irradiance, and no mirror reflection can show a disc narrower than a texel.
  Cubemap run(const Environment& environment, int faceSize) const;

 private:
  Program equirectProgram_;
  Program skyProgram_;
};

}  // namespace pbr
