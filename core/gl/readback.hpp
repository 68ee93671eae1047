#pragma once
#include "core/gl/gl_objects.hpp"
#include "core/scene/image.hpp"

namespace pbr {

// Reads a whole texture through a pixel-pack buffer (one transfer, then one map) and flips it to top-down rows.
ImageRgba8 readbackRgba8(const Texture& texture);
ImageRgbaF readbackRgbaF(const Texture& texture);

}  // namespace pbr
