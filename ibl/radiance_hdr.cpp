#include "ibl/radiance_hdr.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/scene/image.hpp"
#include "core/scene/input_file.hpp"

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
  // Four words, each side in decimal digits: sscanf's %d wrapped 4294967300 to 4 without a word.
  std::istringstream words(text);
  std::string y, h, x, w, extra;
  words >> y >> h >> x >> w;
  const auto side = [](const std::string& digits) -> uint64_t {
    if (digits.empty() || digits.size() > 12 || digits.find_first_not_of("0123456789") != std::string::npos) {
      return 0;
    }
    return std::stoull(digits);
  };
  if (y != "-Y" || x != "+X" || side(h) == 0 || side(w) == 0 || (words >> extra)) {
    in.fail("unsupported Radiance resolution line \"" + text + "\" (expected \"-Y <height> +X <width>\")");
  }
  if (side(w) > uint64_t(kMaxSide) || side(h) > uint64_t(kMaxSide)) {
    in.fail("Radiance image size " + w + "x" + h + " out of range (at most " + std::to_string(kMaxSide) + " a side)");
  }
  // Before the pixels are allocated: a few bytes of runs may declare gigapixels.
  if (overEnvironmentLimit(int64_t(side(w)), int64_t(side(h)))) {
    in.fail("Radiance image size " + environmentLimitText(int64_t(side(w)), int64_t(side(h))));
  }
  width = static_cast<int>(side(w));
  height = static_cast<int>(side(h));
}

// One RGBE pixel as linear RGB, alpha 1: mantissas times 2^(e - 128 - 8), zero for e = 0 (Ward 1991, "Real Pixels").
void storeRgbe(const unsigned char rgbe[4], float* out) {
  const float scale = rgbe[3] == 0 ? 0.0f : std::ldexp(1.0f, int(rgbe[3]) - (128 + 8));
  out[0] = rgbe[0] * scale;
  out[1] = rgbe[1] * scale;
  out[2] = rgbe[2] * scale;
  out[3] = 1.0f;
}

// Decodes the pixels after the header: flat RGBE quadruples (with the original format's runs: a pixel (1, 1, 1, n)
// repeats the one before it n times, n << 8 after another such pixel, and so on: Radiance's oldreadcolrs), or
// (width 8 to 32767) run-length scanlines of four channel runs each. Every length is checked against what is left
// of the scanline and of the file, so a short or malformed file fails with the scanline named and no input can
// loop.
ImageRgbaF decodePixels(HdrReader& in, int width, int height) {
  ImageRgbaF image{width, height, std::vector<float>(size_t{4} * width * height)};
  const auto truncated = [&](int row) {
    in.fail("truncated Radiance file (pixel data ends in scanline " + std::to_string(row) + " of " +
            std::to_string(height) + ")");
  };
  const auto decodeFlat = [&](const unsigned char* first) {
    const size_t pixels = size_t(width) * height;
    unsigned char rgbe[4];
    int shift = 0;
    for (size_t p = 0; p < pixels;) {
      if (!(first && p == 0) && in.left() < 4) truncated(static_cast<int>(p / size_t(width)));
      for (int c = 0; c < 4; ++c) rgbe[c] = first && p == 0 ? first[c] : in.next();
      if (rgbe[0] == 1 && rgbe[1] == 1 && rgbe[2] == 1) {
        const uint64_t repeat = shift < 24 ? uint64_t(rgbe[3]) << shift : pixels;
        if (p == 0 || repeat > pixels - p) {
          in.fail("corrupt Radiance pixel data (a run of " + std::to_string(repeat) + " pixels where " +
                  (p == 0 ? std::string("none precedes it") : std::to_string(pixels - p) + " are left") + ")");
        }
        for (uint64_t i = 0; i < repeat; ++i, ++p) std::copy_n(&image.pixels[(p - 1) * 4], 4, &image.pixels[p * 4]);
        shift += 8;
        continue;
      }
      storeRgbe(rgbe, &image.pixels[p * 4]);
      shift = 0;
      ++p;
    }
  };
  if (width < 8) {
    decodeFlat(nullptr);
    return image;
  }
  std::vector<unsigned char> scanline(size_t{4} * width);  // channel-major: all reds, all greens, ...
  for (int row = 0; row < height; ++row) {
    if (in.left() < 4) truncated(row);
    const unsigned char start[4] = {in.next(), in.next(), in.next(), in.next()};
    if (start[0] != 2 || start[1] != 2 || (start[2] & 0x80)) {
      // Not run-length encoded: the whole picture is flat pixels, from this scanline on.
      if (row > 0) in.fail("Radiance scanline " + std::to_string(row) + " is flat after run-length scanlines");
      decodeFlat(start);
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
