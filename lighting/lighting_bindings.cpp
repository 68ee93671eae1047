#include "lighting/lighting_bindings.hpp"

#include "core/scene/environment_bindings.hpp"
#include "core/scene/frame_block.hpp"
#include "core/scene/shadow_settings.hpp"

namespace pbr {

ShaderDefines lightingBindingDefines() {
  using namespace lighting_binding;
  // Built and checked once: the lighting pass asks for its program every frame.
  static const ShaderDefines defines = bindingDefines(
      {kFrameUbo, kLightingUbo, kClusterUbo, kLightWindowUbo, kDirectionalLightUbo, kSpotWindowUbo, kLegendUbo,
       kLightSsbo, kClusterSsbo, kLightIndexSsbo, kLightVisibleSsbo, kSpotConeSsbo, kClusterStatusSsbo,
       kLightingStatsSsbo, kClusterBoxesSsbo, kClusterSlotsSsbo, kSlotClustersSsbo, kClusterOccupancySsbo,
       kClusterCursorSsbo, kSlotMasksSsbo, kSlotMasksHighSsbo, kBigLightsSsbo, kOccupiedClustersSsbo, kSurfaceTilesSsbo,
       kCasterPlanesUbo, kPlaneSidesSsbo,
       kBaseColorUnit, kNormalUnit, kMaterialUnit, kDepthUnit, kSpecularUnit, kClearcoatUnit, kSheenUnit,
       kRadianceImage, kPartialRadianceImage, kPairCountImage, kAmbientAlbedoUnit, kSheenAlbedoUnit, kIblUbo,
       kIblSpecularUnit, kIblDfgUnit, kIblSheenUnit, kShadowAtlasUnit, kShadowViewSsbo, kLightShadowSsbo, kShadowSquareSsbo,
       kShadowLightImage, kShadowDepthUnit, kShadowOwnerUnit, kOitAccumulationUnit, kOitRevealageUnit, kLayerNodeSsbo});
  return defines;
}

ShaderDefines forwardBindingDefines(const std::vector<BindingPoint>& geometry) {
  using namespace lighting_binding;
  std::vector<BindingPoint> points = {kFrameUbo, kLightingUbo, kClusterUbo, kLightWindowUbo, kDirectionalLightUbo,
                                      kSpotWindowUbo, kLightSsbo, kClusterSsbo, kLightIndexSsbo, kSpotConeSsbo,
                                      kAmbientAlbedoUnit, kSheenAlbedoUnit, kIblUbo, kIblSpecularUnit, kIblDfgUnit,
                                      kIblSheenUnit,
                                      kShadowAtlasUnit, kTransmissionBackgroundUnit,
                                      kShadowViewSsbo, kLightShadowSsbo, kShadowSquareSsbo, kLayerNodeSsbo};
  points.insert(points.end(), geometry.begin(), geometry.end());
  return bindingDefines(points);
}

ShaderDefines occupancyBindingDefines(const std::vector<BindingPoint>& geometry) {
  using namespace lighting_binding;
  std::vector<BindingPoint> points = {kFrameUbo, kClusterUbo, kClusterOccupancySsbo, kCasterPlanesUbo,
                                      kPlaneSidesSsbo};
  points.insert(points.end(), geometry.begin(), geometry.end());
  return bindingDefines(points);
}

}  // namespace pbr
