#pragma once
#include "core/gl/shader_library.hpp"

namespace pbr {

// The split-sum DFG table (shaders/ibl/dfg.comp): RG16F, size x size, texel (x, y) at n.v = x / (size - 1) and
// perceptual roughness y / (size - 1) holds (A, B), F0 A + B being the directional albedo of the renderer's
// specular lobe. It depends on the BRDF only, not on the environment.
class DfgTablePass {
 public:
  explicit DfgTablePass(const ShaderLibrary& shaders);
  Texture run(int size, int samples) const;

 private:
  Program program_;
};

}  // namespace pbr
