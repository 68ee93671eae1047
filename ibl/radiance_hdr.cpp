#include "ibl/radiance_hdr.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/image.hpp"
#include "core/input_file.hpp"

namespace pbr {

namespace {

// Header lines up to 1024 bytes; run-length scanlines are 8 to 32767 pixels wide, the 15 bits of their length.
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

// One RGBE pixel as linear RGB, alpha 1: mantissas times 2^(e - 128 - 8), zero for e = 0 (Ward 1991, "Real Pixels").
void storeRgbe(const unsigned char rgbe[4], float* out) {
  const float scale = rgbe[3] == 0 ? 0.0f : std::ldexp(1.0f, int(rgbe[3]) - (128 + 8));
  out[0] = rgbe[0] * scale;
  out[1] = rgbe[1] * scale;
  out[2] = rgbe[2] * scale;
  out[3] = 1.0f;
}

// Decodes the pixels after the header: flat RGBE quadruples, or (width 8 to 32767) run-length scanlines of four
// channel runs each. Every length is checked against what is left of the scanline and of the file, so a short or
// malformed file fails with the scanline named and no input can loop.
ImageRgbaF decodePixels(HdrReader& in, int width, int height) {
  ImageRgbaF image{width, height, std::vector<float>(size_t{4} * width * height)};
  const size_t flatBytes = size_t{4} * width * height;
  const auto truncated = [&](int row) {
    in.fail("truncated Radiance file (pixel data ends in scanline " + std::to_string(row) + " of " +
            std::to_string(height) + ")");
  };
  const auto decodeFlat = [&](size_t firstPixel, const unsigned char* first) {
    unsigned char rgbe[4];
    for (size_t p = firstPixel; p < size_t(width) * height; ++p) {
      for (int c = 0; c < 4; ++c) rgbe[c] = first && p == firstPixel ? first[c] : in.next();
      storeRgbe(rgbe, &image.pixels[p * 4]);
    }
  };
  if (width < 8) {
    if (in.left() < flatBytes) truncated(static_cast<int>(in.left() / (size_t{4} * width)));
    decodeFlat(0, nullptr);
    return image;
  }
  std::vector<unsigned char> scanline(size_t{4} * width);  // channel-major: all reds, all greens, ...
  for (int row = 0; row < height; ++row) {
    if (in.left() < 4) truncated(row);
    const unsigned char start[4] = {in.next(), in.next(), in.next(), in.next()};
    if (start[0] != 2 || start[1] != 2 || (start[2] & 0x80)) {
      // Not run-length encoded: the whole picture is flat pixels, from this scanline on.
      if (row > 0) in.fail("Radiance scanline " + std::to_string(row) + " is flat after run-length scanlines");
      if (in.left() + 4 < flatBytes) truncated(static_cast<int>((in.left() + 4) / (size_t{4} * width)));
      decodeFlat(0, start);
      return image;
    }
    if (((start[2] << 8) | start[3]) != width) {
      in.fail("corrupt Radiance scanline " + std::to_string(row) + " (its length " +
              std::to_string((start[2] << 8) | start[3]) + " is not the width " + std::to_string(width) + ")");
    }
    for (int channel = 0; channel < 4; ++channel) {
      unsigned char* out = &scanline[size_t(channel) * width];
      for (int x = 0; x < width;) {
        if (in.left() < 1) truncated(row);
        const unsigned count = in.next();
        const bool run = count > 128;
        const unsigned n = run ? count - 128 : count;
        if (n == 0 || n > static_cast<unsigned>(width - x)) {
          in.fail("corrupt Radiance scanline " + std::to_string(row) + " (a run of " + std::to_string(n) +
                  " pixels where " + std::to_string(width - x) + " are left)");
        }
        if (in.left() < (run ? 1 : n)) truncated(row);
        if (run) {
          std::fill_n(out + x, n, in.next());
        } else {
          for (unsigned i = 0; i < n; ++i) out[x + int(i)] = in.next();
        }
        x += static_cast<int>(n);
      }
    }
    for (int x = 0; x < width; ++x) {
      const unsigned char rgbe[4] = {scanline[size_t(x)], scanline[size_t(width) + x], scanline[size_t(2) * width + x],
                                     scanline[size_t(3) * width + x]};
      storeRgbe(rgbe, &image.pixels[(size_t(row) * width + x) * 4]);
    }
  }
  return image;
}

}  // namespace

ImageRgbaF readRadianceHdr(const std::string& path) {
  const std::string text = readInputFile(path);
  const std::vector<unsigned char> bytes(text.begin(), text.end());

  HdrReader reader(path, bytes);
  int width = 0, height = 0;
  readHeader(reader, width, height);
  return decodePixels(reader, width, height);
}

}  // namespace pbr
