#include "ibl/openexr_image.hpp"

#include <tinyexr.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <stdexcept>

#include "core/file_names.hpp"
#include "core/input_file.hpp"
#include "core/messages.hpp"
#include "ibl/radiance_hdr.hpp"

namespace pbr {

namespace {

// The Radiance reader's bound, so that either file of one picture loads or neither does.
constexpr int kMaxSide = 32767;

std::string takeError(const char* err, const std::string& fallback) {
  std::string text = err ? err : fallback;
  if (err) FreeEXRErrorMessage(err);
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ' || text.back() == '.')) text.pop_back();
  return text.empty() ? fallback : text;
}

}  // namespace

bool hasOpenExrMagic(const std::string& bytes) {
  return bytes.size() >= 4 && bytes.compare(0, 4, std::string("\x76\x2f\x31\x01", 4)) == 0;
}

ImageRgbaF readOpenExr(const std::string& path) {
  const std::string bytes = readInputFile(path);
  if (!hasOpenExrMagic(bytes)) throw std::runtime_error(path + ": not an OpenEXR file (no EXR magic number)");
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  EXRVersion version;
  if (ParseEXRVersionFromMemory(&version, data, bytes.size()) != TINYEXR_SUCCESS) {
    throw std::runtime_error(path + ": unsupported or damaged OpenEXR version field");
  }
  if (version.multipart || version.non_image) {
    throw std::runtime_error(path + ": a multi-part or deep OpenEXR file (an environment is one scanline image)");
  }
  EXRHeader header;
  InitEXRHeader(&header);
  const char* err = nullptr;
  if (ParseEXRHeaderFromMemory(&header, &version, data, bytes.size(), &err) != TINYEXR_SUCCESS) {
    FreeEXRHeader(&header);
    throw std::runtime_error(path + ": damaged OpenEXR header: " + oneLine(takeError(err, "unreadable")));
  }
  const int64_t width = int64_t(header.data_window.max_x) - header.data_window.min_x + 1;
  const int64_t height = int64_t(header.data_window.max_y) - header.data_window.min_y + 1;
  FreeEXRHeader(&header);
  if (width < 1 || height < 1 || width > kMaxSide || height > kMaxSide) {
    throw std::runtime_error(path + ": OpenEXR image size " + std::to_string(width) + "x" + std::to_string(height) +
                             " out of range (at most " + std::to_string(kMaxSide) + " a side)");
  }
  float* rgba = nullptr;
  int w = 0, h = 0;
  if (LoadEXRFromMemory(&rgba, &w, &h, data, bytes.size(), &err) != TINYEXR_SUCCESS) {
    throw std::runtime_error(path + ": cannot decode the OpenEXR image: " + oneLine(takeError(err, "unreadable")));
  }
  const std::unique_ptr<float, void (*)(void*)> owned(rgba, std::free);
  if (w != width || h != height) throw std::runtime_error(path + ": OpenEXR data window and pixels disagree");
  ImageRgbaF image{w, h, std::vector<float>(rgba, rgba + size_t(w) * size_t(h) * 4)};
  size_t repaired = 0;
  for (size_t i = 0; i < image.pixels.size(); ++i) {
    float& v = image.pixels[i];
    if (i % 4 == 3) {
      v = 1.0f;  // an environment's alpha means nothing
    } else if (!(std::isfinite(v) && v >= 0.0f)) {
      v = 0.0f;
      ++repaired;
    }
  }
  if (repaired > 0) {
    warnOnce(path + ": " + std::to_string(repaired) + " channel values negative, NaN or infinite, read as 0 (an "
             "environment's radiance is finite and at least 0)");
  }
  return image;
}

ImageRgbaF readEnvironmentImage(const std::string& path) {
  if (lowerExtension(path) == ".exr") return readOpenExr(path);
  // A Radiance file is read by name or by content alike; the magic number decides for other names.
  requireRegularFile(path);
  std::string head(4, '\0');
  std::ifstream in(path, std::ios::binary);
  in.read(head.data(), 4);
  head.resize(size_t(std::max<std::streamsize>(in.gcount(), 0)));
  return hasOpenExrMagic(head) ? readOpenExr(path) : readRadianceHdr(path);
}

}  // namespace pbr
