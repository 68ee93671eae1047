#include "lighting/lighting_bindings.hpp"

#include "core/environment_maps.hpp"
#include "core/frame_block.hpp"

namespace pbr {

ShaderDefines lightingBindingDefines() {
  using namespace lighting_binding;
  return bindingDefines({kFrameUbo, kLightingUbo, kClusterUbo, kLightSsbo, kClusterSsbo, kLightIndexSsbo,
                         kLightVisibleSsbo, kClusterBoundsSsbo, kClusterStatusSsbo, kLightingStatsSsbo,
                         kClusterViewLightsSsbo, kClusterTileMasksSsbo, kBaseColorUnit, kNormalUnit, kMaterialUnit,
                         kDepthUnit, kAmbientAlbedoUnit, kIblUbo, kIblSpecularUnit, kIblDfgUnit});
}

}  // namespace pbr
