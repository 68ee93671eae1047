#pragma once
#include <cstddef>
#include <vector>

#include "core/scene/image.hpp"
#include "reference/reference_renderer.hpp"

namespace pbr {

// One light's visibility as a GPU frame shows it, per pixel: the frame lit by that light alone, shadowed, over the
// same frame unshadowed (sums of the RGB channels), -1 where the unshadowed frame is black (nothing to compare).
// The lighting pass gives no per-light visibility, so the ratio of two frames is the only way to read it back.
std::vector<float> visibilityRatio(const ImageRgbaF& shadowed, const ImageRgbaF& unshadowed);

// The lit/shadowed state of one light in a GPU frame against the reference's shadow rays. A pixel is lit where its
// visibility is at least 0.5. Compared: pixels inside an object and away from its silhouette
// (ReferenceFrame::interior) where both have a visibility (>= 0), and more than `band` pixels (Chebyshev distance)
// from any change of the reference's state (lit, shadowed, or not lit by the light at all): the penumbra band,
// where a filter's soft edge, the map's texels and the rasterizer's rounding may decide either way.
struct ShadowAgreement {
  size_t compared = 0;
  size_t shadowed = 0;       // of those, shadowed in the reference
  size_t misclassified = 0;  // of those, lit in one and shadowed in the other
  double misclassifiedShare() const { return compared ? double(misclassified) / double(compared) : 0.0; }
  ShadowAgreement& operator+=(const ShadowAgreement& other);
};
// `ref` is the reference frame of the same light alone, with shadows (its `visibility` filled, one light: 0 or 1).
ShadowAgreement compareShadowState(const std::vector<float>& visibility, const reference::ReferenceFrame& ref,
                                   int band);

}  // namespace pbr
