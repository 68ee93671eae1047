#include "gbuffer/gbuffer_bindings.hpp"

#include "core/scene/frame_block.hpp"

namespace pbr {

std::vector<BindingPoint> materialMapBindings() {
  using namespace gbuffer_binding;
  return {kBaseColorMapUnit,      kMetallicRoughnessMapUnit, kNormalMapUnit,           kOcclusionMapUnit,
          kEmissiveMapUnit,       kClearcoatMapUnit,         kClearcoatRoughnessMapUnit, kClearcoatNormalMapUnit,
          kSheenColorMapUnit,     kSheenRoughnessMapUnit,    kSpecularMapUnit,         kSpecularColorMapUnit,
          kTransmissionMapUnit,   kThicknessMapUnit};
}

ShaderDefines gbufferBindingDefines() {
  using namespace gbuffer_binding;
  std::vector<BindingPoint> points = {kFrameUbo, kObjectUbo, kShadowViewsUbo};
  const std::vector<BindingPoint> maps = materialMapBindings();
  points.insert(points.end(), maps.begin(), maps.end());
  return bindingDefines(points);
}

}  // namespace pbr
