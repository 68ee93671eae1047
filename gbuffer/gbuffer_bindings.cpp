#include "gbuffer/gbuffer_bindings.hpp"

#include "core/frame_block.hpp"

namespace pbr {

ShaderDefines gbufferBindingDefines() {
  using namespace gbuffer_binding;
  return bindingDefines({kFrameUbo, kObjectUbo, kBaseColorMapUnit, kMetallicRoughnessMapUnit, kNormalMapUnit,
                         kOcclusionMapUnit, kEmissiveMapUnit});
}

}  // namespace pbr
