#include "ibl/radiance_hdr.hpp"

#include <stb_image.h>

#include <cstdio>
#include <memory>
#include <stdexcept>
#include <vector>

#include "core/image.hpp"
#include "core/input_file.hpp"

namespace pbr {

namespace {

// stb_image's limits: header lines up to 1024 bytes, run-length scanlines 8 to 32767 pixels wide.
constexpr size_t kMaxHeaderLine = 1024;
constexpr int kMaxSide = 32767;

class HdrReader {
 public:
  HdrReader(const std::string& path, const std::vector<unsigned char>& bytes) : path_(path), bytes_(bytes) {}

  [[noreturn]] void fail(const std::string& what) const { throw std::runtime_error(path_ + ": " + what); }

  // One header line without its newline; false at the end of the file.
  bool line(std::string& out) {
    out.clear();
    while (pos_ < bytes_.size() && bytes_[pos_] != '\n') {
      if (out.size() == kMaxHeaderLine) fail("Radiance header line longer than 1024 bytes");
      out += static_cast<char>(bytes_[pos_++]);
    }
    if (pos_ == bytes_.size()) return false;
    ++pos_;
    return true;
  }

  size_t left() const { return bytes_.size() - pos_; }
  unsigned char next() { return bytes_[pos_++]; }
  void skip(size_t n) { pos_ += n; }

 private:
  const std::string& path_;
  const std::vector<unsigned char>& bytes_;
  size_t pos_ = 0;
};

void readHeader(HdrReader& in, int& width, int& height) {
  std::string text;
  const bool more = in.line(text);
  if ((text != "#?RADIANCE" && text != "#?RGBE") || !more) {
    in.fail("not a Radiance RGBE file (it does not start with a \"#?RADIANCE\" or \"#?RGBE\" line)");
  }
  bool rgbe = false;
  for (;;) {
    if (!in.line(text)) in.fail("truncated Radiance header (no blank line before the resolution)");
    if (text.empty()) break;
    if (text.rfind("FORMAT=", 0) == 0) {
      if (text != "FORMAT=32-bit_rle_rgbe") in.fail("unsupported Radiance " + text + " (expected 32-bit_rle_rgbe)");
      rgbe = true;
    }
  }
  if (!rgbe) in.fail("Radiance header has no FORMAT=32-bit_rle_rgbe line");
  if (!in.line(text)) in.fail("truncated Radiance header (no resolution line)");
  char extra = 0;
  if (std::sscanf(text.c_str(), "-Y %d +X %d %c", &height, &width, &extra) != 2) {
    in.fail("unsupported Radiance resolution line \"" + text + "\" (expected \"-Y <height> +X <width>\")");
  }
  if (width < 1 || height < 1 || width > kMaxSide || height > kMaxSide) {
    in.fail("Radiance image size " + std::to_string(width) + "x" + std::to_string(height) + " out of range");
  }
}

// Walks the pixel data the way stb_image will decode it, so that a short or malformed file fails here instead.
void checkPixels(HdrReader& in, int width, int height) {
  const size_t flatBytes = size_t{4} * width * height;
  const auto truncated = [&](int row) {
    in.fail("truncated Radiance file (pixel data ends in scanline " + std::to_string(row) + " of " +
            std::to_string(height) + ")");
  };
  if (width < 8) {
    if (in.left() < flatBytes) truncated(static_cast<int>(in.left() / (size_t{4} * width)));
    return;
  }
  for (int row = 0; row < height; ++row) {
    if (in.left() < 4) truncated(row);
    const unsigned char c1 = in.next(), c2 = in.next(), hi = in.next(), lo = in.next();
    if (c1 != 2 || c2 != 2 || (hi & 0x80)) {
      // Not run-length encoded: stb_image then reads the whole picture as flat pixels, from this scanline on.
      if (row > 0) in.fail("Radiance scanline " + std::to_string(row) + " is flat after run-length scanlines");
      if (in.left() + 4 < flatBytes) truncated(static_cast<int>((in.left() + 4) / (size_t{4} * width)));
      return;
    }
    if (((hi << 8) | lo) != width) {
      in.fail("corrupt Radiance scanline " + std::to_string(row) + " (its length " + std::to_string((hi << 8) | lo) +
              " is not the width " + std::to_string(width) + ")");
    }
    for (int channel = 0; channel < 4; ++channel) {
      for (int x = 0; x < width;) {
        if (in.left() < 1) truncated(row);
        const unsigned count = in.next();
        const bool run = count > 128;
        const unsigned n = run ? count - 128 : count;
        if (n == 0 || n > static_cast<unsigned>(width - x)) {
          in.fail("corrupt Radiance scanline " + std::to_string(row) + " (a run of " + std::to_string(n) +
                  " pixels where " + std::to_string(width - x) + " are left)");
        }
        const size_t payload = run ? 1 : n;
        if (in.left() < payload) truncated(row);
        in.skip(payload);
        x += static_cast<int>(n);
      }
    }
  }
}

}  // namespace

ImageRgbaF readRadianceHdr(const std::string& path) {
  const std::string text = readInputFile(path);
  const std::vector<unsigned char> bytes(text.begin(), text.end());

  HdrReader reader(path, bytes);
  int width = 0, height = 0;
  readHeader(reader, width, height);
  checkPixels(reader, width, height);

  int w = 0, h = 0, channels = 0;
  std::unique_ptr<float, void (*)(void*)> pixels(
      stbi_loadf_from_memory(bytes.data(), static_cast<int>(bytes.size()), &w, &h, &channels, 4), stbi_image_free);
  if (!pixels) reader.fail("cannot decode Radiance pixels" + decoderFailureReason());
  if (w != width || h != height) reader.fail("decoded size differs from the header");
  ImageRgbaF image;
  image.width = w;
  image.height = h;
  image.pixels.assign(pixels.get(), pixels.get() + size_t{4} * w * h);
  return image;
}

}  // namespace pbr
