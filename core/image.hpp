#pragma once
#include <cstddef>
#include <cstdint>
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

// Each throws std::runtime_error naming the file on failure.
void writePng(const std::string& path, const ImageRgba8& image);
// Any image stb decodes (PNG, JPEG, ...), read through readInputFile and decoded by decodeImage.
ImageRgba8 readPng(const std::string& path);
// Decodes PNG, JPEG and the other formats stb reads to RGBA8 (16-bit images narrowed to 8 bits). Throws
// std::runtime_error("NAME: cannot decode image: REASON"), or "NAME: cannot decode image" where the decoder gives
// no reason (stb leaves none for some corrupt files).
ImageRgba8 decodeImage(const unsigned char* bytes, size_t size, const std::string& name);
// ": REASON" for the last stb decoder failure, or "" where stb gives none (it may give a null pointer).
std::string decoderFailureReason();
void writeExr(const std::string& path, const ImageRgbaF& image);  // RGB float32
void writePfm(const std::string& path, const ImageRgbaF& image);  // RGB float32, little endian
// Chooses EXR or PFM by the file's extension.
void writeHdr(const std::string& path, const ImageRgbaF& image);

}  // namespace pbr
