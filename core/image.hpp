#pragma once
#include <cstddef>
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace pbr {

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

// The file formats of captures, chosen by extension (case-insensitive). Throw std::invalid_argument naming the
// file for any other extension, so that a command can refuse the path before it renders anything.
// A device or FIFO (/dev/stdout) names no format: display images go there as PNG.
enum class HdrFileFormat { Exr, Pfm };
HdrFileFormat hdrFileFormat(const std::string& path);  // .exr or .pfm
enum class LdrFileFormat { Png, Jpeg };
LdrFileFormat ldrFileFormat(const std::string& path);  // .png, .jpg or .jpeg

// Encoders onto a stream (an OutputFile's, core/output_file.hpp, which checks the writes).
void writePng(std::ostream& out, const ImageRgba8& image);
void writeJpeg(std::ostream& out, const ImageRgba8& image);  // baseline, quality 95, alpha dropped
void writeLdr(std::ostream& out, LdrFileFormat format, const ImageRgba8& image);
void writeExr(std::ostream& out, const ImageRgbaF& image);  // RGB float32
void writePfm(std::ostream& out, const ImageRgbaF& image);  // RGB float32, little endian
void writeHdr(std::ostream& out, HdrFileFormat format, const ImageRgbaF& image);

// Whole files through an OutputFile: a failure throws std::runtime_error "PATH: cannot write: REASON" and leaves
// no file behind. writePng writes PNG whatever the name; writeLdr picks by the extension, as ldrFileFormat.
void writePng(const std::string& path, const ImageRgba8& image);
void writeLdr(const std::string& path, const ImageRgba8& image);
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
void writeHdr(const std::string& path, const ImageRgbaF& image);  // EXR or PFM by the extension

}  // namespace pbr
