#pragma once
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "app/accuracy/accuracy_metrics.hpp"
#include "app/accuracy/accuracy_variants.hpp"
#include "app/accuracy/shadow_metrics.hpp"
#include "core/scene/shadow_settings.hpp"
#include "renderer/renderer.hpp"

namespace pbr {

// A shadow setting `pbr accuracy` measures: the exact PBR variant (the reference's model, so that shadows are the
// only difference left) with these shadow maps, or with none.
struct ShadowRow {
  std::string name;  // "unshadowed", "shadow-pcf3x3-4096"
  ShadowSettings settings;  // mode None for the unshadowed row, else Auto: the scene's lights cast as it says
};

// The rows measured unless --shadow-rows says otherwise.
extern const char* const kDefaultShadowRows;
// Comma-separated: "unshadowed", "FILTER" (the default atlas) or "FILTER:ATLAS" (a power of two from 256 to
// 16384), or "none" for no rows; throws std::invalid_argument naming the bad item.
std::vector<ShadowRow> parseShadowRows(const std::string& list);

// The frame options of a row: the exact variant's (exactVariantOptions) with the row's shadow settings; rendered
// with exactVariantConfig().
FrameOptions shadowRowOptions(const ShadowRow& row, const Scene& scene);

// Pixels within this many of a change of the reference's lit/shadowed state are not compared (the penumbra band).
constexpr int kShadowBandPx = 2;

struct ShadowRowResult {
  ErrorMetrics error;          // the whole shadowed frame against the shadowed reference
  ShadowAgreement agreement;   // lit/shadowed state, every casting light alone, summed over the lights
  std::vector<float> relativeError;  // per pixel, for the error map
};

// What every row is compared with, made once: the scene's shadowed reference frame, and per light that casts, the
// reference frame of that light alone (its shadow rays) and the unshadowed GPU frame of that light alone (the
// denominator of visibilityRatio). Lights alone are rendered without ambient light, whose share would blur the
// ratio.
class ShadowComparison {
 public:
  ShadowComparison(const ShaderLibrary& shaders, const Scene& scene, glm::ivec2 size,
                   const reference::ReferenceOptions& referenceOptions, TimingMode timing,
                   ToneCurve curve = ToneCurve::AcesHill);
  ShadowRowResult measure(const ShadowRow& row) const;
  size_t castingLights() const { return lights_.size(); }

 private:
  struct LightAlone {
    Scene scene;
    reference::ReferenceFrame reference;
    ImageRgbaF unshadowed;
  };
  const ShaderLibrary& shaders_;
  Scene scene_;
  glm::ivec2 size_;
  ToneCurve curve_;  // of the display images the error in 8-bit levels is measured on
  TimingMode timing_;
  reference::ReferenceFrame reference_;
  ImageRgba8 referenceLdr_;
  std::vector<LightAlone> lights_;
};

}  // namespace pbr
