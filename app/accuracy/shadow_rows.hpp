#pragma once
#include <string>
#include <vector>

#include "app/accuracy/accuracy_metrics.hpp"
#include "app/accuracy/accuracy_variants.hpp"
#include "app/accuracy/shadow_metrics.hpp"
#include "core/scene/shadow_settings.hpp"
#include "renderer/frame_options.hpp"

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
// One item of that list.
ShadowRow parseShadowRow(const std::string& item);

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

}  // namespace pbr
