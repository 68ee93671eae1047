#pragma once
#include <glm/vec4.hpp>

#include "core/gl/shader_library.hpp"
#include "ibl/cubemap.hpp"

namespace pbr {

// Mirrors IblBlock in shaders/ibl/ibl_sample.glsl: the environment's radiance projected onto the 9 spherical
// harmonics of bands 0-2, rgb, in the order of shaders/ibl/sh9.glsl.
struct IblBlock {
  glm::vec4 sh[9];
};
static_assert(sizeof(IblBlock) == 144, "std140 layout of IblBlock");

// Projects an environment cube map (its finest level with faces of at most 256^2) onto IblBlock's coefficients
// on the GPU, in two passes (shaders/ibl/sh_project.comp, sh_reduce.comp). The result is a buffer holding one
// IblBlock, written by the GPU and bound as the lighting pass's IBL_UBO without a round trip through the CPU.
class IrradianceShPass {
 public:
  explicit IrradianceShPass(const ShaderLibrary& shaders);
  Buffer run(const Cubemap& environment) const;

 private:
  Program projectProgram_;
  Program reduceProgram_;
};

}  // namespace pbr
