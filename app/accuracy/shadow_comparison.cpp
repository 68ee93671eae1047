#include "app/accuracy/shadow_comparison.hpp"

#include "renderer/display_image.hpp"
#include "renderer/offscreen.hpp"

namespace pbr {

ShadowComparison::ShadowComparison(const ShaderLibrary& shaders, const Scene& scene, glm::ivec2 size,
                                   const reference::ReferenceOptions& referenceOptions, TimingMode timing,
                                   ToneCurve curve)
    : shaders_(shaders), scene_(scene), size_(size), curve_(curve), timing_(timing) {
  reference::ReferenceOptions options = referenceOptions;
  options.shadows = ShadowMode::Auto;
  reference_ = reference::renderReference(scene, size.x, size.y, options);
  referenceLdr_ = displayImage(shaders, reference_.radiance, scene.displayExposure(), curve);
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
  FrameOptions options = shadowRowOptions(row, scene_);
  options.toneCurve = curve_;
  const RenderedFrames f = renderOffscreen(shaders_, scene_, size_, options, 3, config, timing_);
  r.error = measureError(f.hdr, f.ldr, reference_, referenceLdr_);
  r.relativeError = relativeErrorPerPixel(f.hdr, reference_);
  for (const LightAlone& l : lights_) {
    const ImageRgbaF shadowed =
        renderOffscreen(shaders_, l.scene, size_, shadowRowOptions(row, l.scene), 2, config, timing_).hdr;
    r.agreement += compareShadowState(visibilityRatio(shadowed, l.unshadowed), l.reference, kShadowBandPx);
  }
  return r;
}

}  // namespace pbr
