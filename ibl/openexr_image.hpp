#pragma once
#include <string>

#include "core/scene/image.hpp"

namespace pbr {

// Reads an OpenEXR picture (single part, scanline or tiled, half or float channels; R, G and B, or one luminance
// channel as grey) into linear RGB with alpha 1, rows from the top, through tinyexr. The header's data window is
// checked against the Radiance reader's limit (32767 a side) before tinyexr allocates; radiance an environment
// cannot hold (negative, NaN or infinite) is read as 0, the count said in one warning line. Throws
// std::runtime_error, one line naming the file and what is wrong with it.
ImageRgbaF readOpenExr(const std::string& path);

// Whether `bytes` begin with OpenEXR's magic number.
bool hasOpenExrMagic(const std::string& bytes);

// The environment picture of a file: OpenEXR by its magic number or a .exr name, else Radiance RGBE.
ImageRgbaF readEnvironmentImage(const std::string& path);

}  // namespace pbr
