#pragma once
#include <cstddef>
#include <vector>

#include "core/scene/image.hpp"
#include "reference/reference_renderer.hpp"

namespace pbr {

// A GPU frame against the CPU reference, over the pixels inside objects (silhouettes and background left out).
struct ErrorMetrics {
  double relativeRmse = 0.0;  // sqrt(sum (gpu - ref)^2 / sum ref^2), linear HDR colour channels
  double meanLevels = 0.0;    // mean |difference| of the 8-bit colour channels after post
  double maxLevels = 0.0;
  double shareOver2 = 0.0;    // share of pixels with a channel more than 2 levels off
  size_t pixels = 0;
};

ErrorMetrics measureError(const ImageRgbaF& hdr, const ImageRgba8& ldr, const reference::ReferenceFrame& ref,
                          const ImageRgba8& refLdr);

// |gpu - ref| / |ref| per pixel (RGB norms), NaN where not compared; |ref| is floored at 1e-3 of its mean so
// that black pixels do not divide by zero.
std::vector<float> relativeErrorPerPixel(const ImageRgbaF& hdr, const reference::ReferenceFrame& ref);

}  // namespace pbr
