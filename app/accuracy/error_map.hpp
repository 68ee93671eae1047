#pragma once
#include <vector>

#include "core/scene/image.hpp"

namespace pbr {

// Paints `values` (width x height, row 0 at the top; NaN marks pixels without a value, drawn grey) on a log10
// colour scale from `lo` to `hi` (both > 0, whole decades), enlarged to at least 320 pixels wide, with a colour
// bar below labelled at every decade.
ImageRgba8 errorMapImage(const std::vector<float>& values, int width, int height, double lo, double hi);

}  // namespace pbr
