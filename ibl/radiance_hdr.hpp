#pragma once
#include <string>

#include "core/image.hpp"

namespace pbr {

// Reads a Radiance RGBE picture (.hdr: "#?RADIANCE" or "#?RGBE", FORMAT=32-bit_rle_rgbe, "-Y height +X width",
// flat or new-style run-length scanlines) into linear RGB with alpha 1, rows from the top. The file is checked
// in full before stb_image decodes it: stb_image reads past the end of a truncated file as zeros (and loops
// forever on a zero run length), and says little more than "corrupt" otherwise. Throws std::runtime_error, one
// line naming the file and what is wrong with it.
ImageRgbaF readRadianceHdr(const std::string& path);

}  // namespace pbr
