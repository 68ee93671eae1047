#pragma once
#include <string>

#include "core/scene/image.hpp"

namespace pbr {

// Reads a Radiance RGBE picture (.hdr: "#?RADIANCE" or "#?RGBE", FORMAT=32-bit_rle_rgbe, "-Y height +X width",
// flat or new-style run-length scanlines) into linear RGB with alpha 1, rows from the top. It decodes the pixels
// itself, checking every run against the scanline and the file, rather than through stb_image, which reads past
// the end of a truncated file as zeros and loops forever on some malformed headers and runs (fuzz/regressions/).
// Throws std::runtime_error, one line naming the file and what is wrong with it.
ImageRgbaF readRadianceHdr(const std::string& path);

}  // namespace pbr
