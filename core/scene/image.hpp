#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace pbr {

// Images in memory and the decoding of the image files a scene names; writing them is core/io/image_output.hpp's.

// Pixels in rows from the top, as image files store them.
struct ImageRgba8 {
  int width = 0, height = 0;
  std::vector<uint8_t> pixels;  // 4 bytes per pixel
};
struct ImageRgbaF {
  int width = 0, height = 0;
  std::vector<float> pixels;  // 4 floats per pixel
  const float* at(int x, int y) const { return &pixels[(static_cast<size_t>(y) * width + x) * 4]; }
};

// Any image decodeImage decodes (PNG, JPEG, WebP), read through readInputFile.
ImageRgba8 readPng(const std::string& path);
// What decodeImage accepts: 16384 pixels a side and 2^26 pixels (8192 x 8192) in all, checked on the header
// before the decoder allocates.
constexpr int kMaxImageSide = 16384;
constexpr int64_t kMaxImagePixels = int64_t(1) << 26;
// Whether a header's declared size is over those limits, and "WxH pixels, over the image limit (16384 a side,
// 67108864 pixels in all)".
bool overImageLimit(int64_t width, int64_t height);
std::string imageLimitText(int64_t width, int64_t height);
// Environment images (Radiance, OpenEXR) keep their formats' sides (the context's texture size is checked where
// they are uploaded) but not more pixels in all (1 GiB as float RGBA): a file of a few bytes may declare
// gigapixels. The text: "WxH is N pixels, over the limit of 67108864 (1 GiB as float RGBA)".
bool overEnvironmentLimit(int64_t width, int64_t height);
std::string environmentLimitText(int64_t width, int64_t height);

// Decodes PNG and JPEG (stb_image) and WebP (libwebp) to RGBA8 (16-bit images narrowed to 8 bits); any other
// format is refused. Throws
// std::runtime_error("NAME: cannot decode image: REASON"), or "NAME: cannot decode image" where the decoder gives
// no reason (stb leaves none for some corrupt files).
ImageRgba8 decodeImage(const unsigned char* bytes, size_t size, const std::string& name);
// The MIME type of the format decodeImage would decode `bytes` as, by their signature: "image/png", "image/jpeg",
// "image/webp", or null for none of them.
const char* imageMimeType(const unsigned char* bytes, size_t size);
// ": REASON" for the last stb decoder failure, or "" where stb gives none (it may give a null pointer).
std::string decoderFailureReason();

}  // namespace pbr
