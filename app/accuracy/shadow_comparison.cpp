#include "app/accuracy/shadow_comparison.hpp"

#include "renderer/display_image.hpp"
#include "renderer/offscreen.hpp"

namespace pbr {

namespace {

reference::ReferenceOptions withShadowRays(reference::ReferenceOptions options) {
  options.shadows = ShadowMode::Auto;
  return options;
}

}  // namespace

ShadowComparison::ShadowComparison(const ShaderLibrary& shaders, const Scene& scene, glm::ivec2 size,
                                   const reference::ReferenceOptions& referenceOptions, TimingMode timing,
                                   ToneCurve curve)
    : frame_(shaders, scene, size, withShadowRays(referenceOptions), timing, curve) {
  const reference::ReferenceOptions options = withShadowRays(referenceOptions);
  Scene dark = scene;
  dark.ambient = glm::vec3(0.0f);
  dark.lights.clear();
  dark.directionalLights.clear();
  std::vector<Scene> alone;
  for (const PointLight& l : scene.lights) {
    if (!castsShadows(l.castsShadows, ShadowMode::Auto)) continue;
    alone.push_back(dark);
    alone.back().lights = {l};
  }
  for (const DirectionalLight& l : scene.directionalLights) {
    if (!castsShadows(l.castsShadows, ShadowMode::Auto)) continue;
    alone.push_back(dark);
    alone.back().directionalLights = {l};
  }
  const ShadowRow unshadowed = parseShadowRow("unshadowed");
  for (Scene& s : alone) {
    LightAlone l{std::move(s), {}, {}};
    l.reference = reference::renderReference(l.scene, size.x, size.y, options);
    const FrameOptions plain = shadowRowOptions(unshadowed, l.scene);
    l.unshadowed = renderOffscreen(shaders, l.scene, size, plain, 2, exactVariantConfig(), timing).hdr;
    lights_.push_back(std::move(l));
  }
}

ShadowRowResult ShadowComparison::measure(const ShadowRow& row) const {
  const RendererConfig config = exactVariantConfig();
  ShadowRowResult r;
  ReferenceComparison::Result whole = frame_.compare(shadowRowOptions(row, frame_.scene()));
  r.error = whole.error;
  r.relativeError = std::move(whole.relativeError);
  for (const LightAlone& l : lights_) {
    const ImageRgbaF shadowed = renderOffscreen(frame_.shaders(), l.scene, frame_.size(),
                                                shadowRowOptions(row, l.scene), 2, config, frame_.timing())
                                    .hdr;
    r.agreement += compareShadowState(visibilityRatio(shadowed, l.unshadowed), l.reference, kShadowBandPx);
  }
  return r;
}

}  // namespace pbr
