#include "ibl/openexr_image.hpp"

#include <tinyexr.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <stdexcept>

#include "core/scene/file_names.hpp"
#include "core/scene/input_file.hpp"
#include "core/scene/messages.hpp"
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
  // The header and the image are freed on every path: tinyexr's LoadEXRFromMemory leaks the header when the pixels
  // fail to decode, so its parts are called here instead.
  struct Parts {
    EXRHeader header;
    EXRImage image;
    Parts() {
      InitEXRHeader(&header);
      InitEXRImage(&image);
    }
    ~Parts() {
      FreeEXRImage(&image);
      FreeEXRHeader(&header);
    }
  } exr;
  EXRHeader& header = exr.header;
  const char* err = nullptr;
  if (ParseEXRHeaderFromMemory(&header, &version, data, bytes.size(), &err) != TINYEXR_SUCCESS) {
    throw std::runtime_error(path + ": damaged OpenEXR header: " + oneLine(takeError(err, "unreadable")));
  }
  const int64_t width = int64_t(header.data_window.max_x) - header.data_window.min_x + 1;
  const int64_t height = int64_t(header.data_window.max_y) - header.data_window.min_y + 1;
  if (width < 1 || height < 1 || width > kMaxSide || height > kMaxSide) {
    throw std::runtime_error(path + ": OpenEXR image size " + std::to_string(width) + "x" + std::to_string(height) +
                             " out of range (at most " + std::to_string(kMaxSide) + " a side)");
  }
  // Before tinyexr allocates the planes.
  if (overEnvironmentLimit(width, height)) {
    throw std::runtime_error(path + ": OpenEXR image size " + environmentLimitText(width, height));
  }
  // R, G and B, or a luminance channel Y read as grey; half and float channels read as float.
  int red = -1, green = -1, blue = -1, grey = -1;
  for (int c = 0; c < header.num_channels; ++c) {
    const std::string name = header.channels[c].name;
    if (name == "R") red = c;
    if (name == "G") green = c;
    if (name == "B") blue = c;
    if (name == "Y") grey = c;
    if (header.pixel_types[c] == TINYEXR_PIXELTYPE_UINT) {
      throw std::runtime_error(path + ": OpenEXR channel " + name + " holds integers, not radiance");
    }
    header.requested_pixel_types[c] = TINYEXR_PIXELTYPE_FLOAT;
  }
  if ((red < 0 || green < 0 || blue < 0) && grey < 0) {
    throw std::runtime_error(path + ": OpenEXR image without R, G and B channels (nor Y)");
  }
  if (LoadEXRImageFromMemory(&exr.image, &header, data, bytes.size(), &err) != TINYEXR_SUCCESS) {
    // A failed load frees what it made itself, leaving pointers FreeEXRImage would free again.
    InitEXRImage(&exr.image);
    throw std::runtime_error(path + ": cannot decode the OpenEXR image: " + oneLine(takeError(err, "unreadable")));
  }
  const int w = static_cast<int>(width), h = static_cast<int>(height);
  ImageRgbaF image{w, h, std::vector<float>(size_t(w) * size_t(h) * 4, 0.0f)};
  const int sources[3] = {red >= 0 ? red : grey, green >= 0 ? green : grey, blue >= 0 ? blue : grey};
  // One block of pixels (the whole image, or a tile) at (x0, y0) of the data window.
  const auto place = [&](unsigned char** planes, int x0, int y0, int bw, int bh) {
    for (int y = 0; y < bh && y0 + y < h; ++y) {
      for (int x = 0; x < bw && x0 + x < w; ++x) {
        float* out = &image.pixels[(size_t(y0 + y) * size_t(w) + size_t(x0 + x)) * 4];
        for (int c = 0; c < 3; ++c) out[c] = reinterpret_cast<const float*>(planes[sources[c]])[y * bw + x];
      }
    }
  };
  if (exr.image.tiles) {
    for (int t = 0; t < exr.image.num_tiles; ++t) {
      const EXRTile& tile = exr.image.tiles[t];
      place(tile.images, tile.offset_x * header.tile_size_x, tile.offset_y * header.tile_size_y, tile.width,
            tile.height);
    }
  } else if (exr.image.images && exr.image.width == w && exr.image.height == h) {
    place(exr.image.images, 0, 0, w, h);
  } else {
    throw std::runtime_error(path + ": OpenEXR data window and pixels disagree");
  }
  size_t repaired = 0;
  for (size_t i = 0; i < image.pixels.size(); ++i) {
    float& v = image.pixels[i];
    if (i % 4 == 3) {
      v = 1.0f;  // an environment's alpha means nothing (and is not read)
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
