#include "gbuffer/gbuffer_bindings.hpp"

#include "core/scene/frame_block.hpp"

namespace pbr {

ShaderDefines gbufferBindingDefines() {
  using namespace gbuffer_binding;
  return bindingDefines({kFrameUbo, kObjectUbo, kShadowViewsUbo, kBaseColorMapUnit, kMetallicRoughnessMapUnit,
                         kNormalMapUnit, kOcclusionMapUnit, kEmissiveMapUnit});
}

}  // namespace pbr
