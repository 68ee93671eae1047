#include "ibl/openexr_image.hpp"

#include <tinyexr.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <vector>

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

// The little-endian integer of `size` bytes at `at`.
uint64_t littleEndian(const std::string& bytes, size_t at, int size) {
  uint64_t v = 0;
  for (int b = size - 1; b >= 0; --b) v = (v << 8) | uint8_t(bytes[at + size_t(b)]);
  return v;
}

// The entries of a channel list as tinyexr reads them (its ReadChannelInfo): a NUL-ended name and 16 bytes each,
// ended by a NUL; -1 where an entry's 16 bytes reach the value's last byte, which tinyexr refuses.
int64_t channelEntries(const std::string& bytes, size_t value, size_t size) {
  const size_t end = value + size;
  size_t at = value;
  int64_t entries = 0;
  while (at < end && bytes[at] != '\0') {
    const size_t nameEnd = bytes.find('\0', at);
    if (nameEnd == std::string::npos || nameEnd >= end || nameEnd + 1 + 16 >= end) return -1;
    at = nameEnd + 1 + 16;
    ++entries;
  }
  return entries;
}

// Debian's tinyexr keeps its asserts, and it asserts, rather than returning an error, on header fields that
// contradict each other: a type that is not the image's kind, a tile description of the wrong size, a level mode
// the format does not define, a tile too large for its level arithmetic. Those fields are read here first, walking
// the attributes as tinyexr does (name, type name, 32-bit size, value). tinyexr converts what it read before
// damage too, so the walk stops where it would (an attribute it cannot read, a compression it does not know, a channel
// list it cannot parse, its limit on attributes) and still checks what came before; the damage is tinyexr's to name.
void checkHeaderFields(const std::string& bytes, const EXRVersion& version, const std::string& path) {
  std::string type;
  bool tiles = false;
  int64_t channels = 0;  // tinyexr adds every channel list's entries to one list and needs one entry
  size_t at = 8;  // past the magic number and the version field
  // tinyexr reads at most TINYEXR_MAX_HEADER_ATTRIBUTES attributes.
  for (int attributes = 0; attributes < TINYEXR_MAX_HEADER_ATTRIBUTES && at < bytes.size() && bytes[at] != '\0';
       ++attributes) {
    const size_t nameEnd = bytes.find('\0', at);
    const size_t typeEnd = nameEnd == std::string::npos ? nameEnd : bytes.find('\0', nameEnd + 1);
    if (typeEnd == std::string::npos || bytes.size() - typeEnd < 5) break;
    const size_t value = typeEnd + 5, size = uint32_t(littleEndian(bytes, typeEnd + 1, 4));
    if (size > bytes.size() - value) break;
    // tinyexr takes an empty value for a string only.
    if (size == 0 && bytes.compare(nameEnd + 1, typeEnd - nameEnd - 1, "string") != 0) break;
    const std::string name = bytes.substr(at, nameEnd - at);
    // tinyexr knows compressions 0 to 4 (none, RLE, ZIPS, ZIP, PIZ; Debian's build has no ZFP).
    if (name == "compression" && size > 0 && uint8_t(bytes[value]) > TINYEXR_COMPRESSIONTYPE_PIZ) break;
    if (name == "channels") {
      const int64_t entries = channelEntries(bytes, value, size);
      if (entries < 0 || channels + entries == 0) break;
      channels += entries;
    }
    if (name == "type") {
      // An empty value leaves the type read before, as tinyexr leaves it.
      const std::string read(bytes.data() + value, strnlen(bytes.data() + value, size));
      if (!read.empty()) type = read;
    } else if (name == "tiles" && version.tiled) {
      if (size != 9) {
        throw std::runtime_error(path + ": OpenEXR header field tiles holds " + std::to_string(size) +
                                 " bytes (a tile description is 9)");
      }
      const auto tileX = uint32_t(littleEndian(bytes, value, 4));
      const auto tileY = uint32_t(littleEndian(bytes, value + 4, 4));
      if (tileX < 1 || tileY < 1 || tileX > uint32_t(kMaxSide) || tileY > uint32_t(kMaxSide)) {
        throw std::runtime_error(path + ": OpenEXR tile size " + std::to_string(tileX) + "x" +
                                 std::to_string(tileY) + " out of range (1 to " + std::to_string(kMaxSide) +
                                 " a side)");
      }
      if ((uint8_t(bytes[value + 8]) & 0x3) > TINYEXR_TILE_RIPMAP_LEVELS) {
        throw std::runtime_error(path + ": OpenEXR header field tiles names level mode 3 (0 to 2 are defined)");
      }
      tiles = true;
    }
    at = value + size;
  }
  // tinyexr reads an image as tiled when the version field says so and a tile description is present.
  const char* kind = tiles ? "tiledimage" : "scanlineimage";
  if (!type.empty() && type != kind) {
    for (char& c : type) c = std::isprint(static_cast<unsigned char>(c)) ? c : '?';
    if (type.size() > 40) type = type.substr(0, 40) + "...";
    throw std::runtime_error(path + ": OpenEXR header field type is \"" + type + "\", but the header describes a " +
                             (tiles ? "tiled" : "scanline") + " image");
  }
}

// Two checks of a tiled image's offset table and tile blocks, which tinyexr trusts:
// - An empty entry (a file whose writing was interrupted) makes tinyexr rebuild the table by walking the tile
//   blocks without bounds (ReconstructTileOffsets), reading past the file.
// - A block naming a tile outside its level makes tinyexr decode a tile of no width or height (it asserts on the
//   empty buffer) or of a size its arithmetic overflows.
// Entries are laid out as tinyexr lays them out: the tiles of every level of the header's level mode (one level,
// mipmaps or ripmaps, sides rounded down or up; ripmaps by level row, then column), row by row, one 64-bit offset
// each, after the header. A table that runs past the file, or a block that does, is left to tinyexr, which says so;
// so is a block of another level, which it skips.
void checkTileOffsets(const std::string& bytes, const EXRHeader& header, int64_t width, int64_t height,
                      const std::string& path) {
  if (!header.tiled) return;
  const bool up = header.tile_rounding_mode == TINYEXR_TILE_ROUND_UP;
  const auto log2Rounded = [&](int64_t x) {
    int y = 0;
    bool remainder = false;
    for (; x > 1; x >>= 1, ++y) remainder = remainder || (x & 1);
    return y + (up && remainder ? 1 : 0);
  };
  const auto levelSize = [&](int64_t top, int level) {
    const int64_t size = top >> level;
    return std::max<int64_t>(size + (up && (size << level) < top ? 1 : 0), 1);
  };
  const auto tiles = [](int64_t side, int64_t tile) { return (side + tile - 1) / tile; };
  struct Level {
    int x, y;
    int64_t columns, rows;
  };
  std::vector<Level> levels;
  const auto addLevel = [&](int lx, int ly) {
    levels.push_back({lx, ly, tiles(levelSize(width, lx), header.tile_size_x),
                      tiles(levelSize(height, ly), header.tile_size_y)});
  };
  if (header.tile_level_mode == TINYEXR_TILE_RIPMAP_LEVELS) {
    for (int ly = 0; ly <= log2Rounded(height); ++ly) {
      for (int lx = 0; lx <= log2Rounded(width); ++lx) addLevel(lx, ly);
    }
  } else {
    const int count =
        header.tile_level_mode == TINYEXR_TILE_MIPMAP_LEVELS ? log2Rounded(std::max(width, height)) + 1 : 1;
    for (int l = 0; l < count; ++l) addLevel(l, l);
  }
  int64_t entries = 0;
  for (const Level& level : levels) entries += level.columns * level.rows;
  const size_t first = 8 + size_t(header.header_len);
  if (first > bytes.size() || uint64_t(entries) > (bytes.size() - first) / 8) return;
  int64_t i = 0;
  for (const Level& level : levels) {
    for (int64_t tile = 0; tile < level.columns * level.rows; ++tile, ++i) {
      const uint64_t offset = littleEndian(bytes, first + size_t(i) * 8, 8);
      if (int64_t(offset) <= 0) {
        throw std::runtime_error(path + ": OpenEXR tile offset table entry " + std::to_string(i) + " of " +
                                 std::to_string(entries) + " is empty (a file whose writing was interrupted?)");
      }
      if (offset > bytes.size() || bytes.size() - offset < 20) continue;
      const auto x = int32_t(littleEndian(bytes, offset, 4)), y = int32_t(littleEndian(bytes, offset + 4, 4));
      const auto lx = int32_t(littleEndian(bytes, offset + 8, 4)), ly = int32_t(littleEndian(bytes, offset + 12, 4));
      if (lx != level.x || ly != level.y) continue;
      if (x < 0 || y < 0 || x >= level.columns || y >= level.rows) {
        throw std::runtime_error(path + ": OpenEXR tile block " + std::to_string(i) + " names tile (" +
                                 std::to_string(x) + ", " + std::to_string(y) + ") of level (" +
                                 std::to_string(level.x) + ", " + std::to_string(level.y) + "), which has " +
                                 std::to_string(level.columns) + "x" + std::to_string(level.rows) + " tiles");
      }
    }
  }
}

// A scanline image's chunkCount field sizes tinyexr's offset table (8 bytes an entry) before anything compares it
// with the file: a count the file has no room for is refused, so that a few bytes cannot ask for gigabytes.
void checkChunkCount(const std::string& bytes, const EXRHeader& header, const std::string& path) {
  if (header.tiled || header.chunk_count <= 0) return;
  const size_t first = 8 + size_t(header.header_len);
  const uint64_t room = first < bytes.size() ? (bytes.size() - first) / 8 : 0;
  if (uint64_t(header.chunk_count) > room) {
    throw std::runtime_error(path + ": OpenEXR header field chunkCount says " + std::to_string(header.chunk_count) +
                             " blocks, but the file has room for " + std::to_string(room) + " block offsets");
  }
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
  checkHeaderFields(bytes, version, path);
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
  checkTileOffsets(bytes, header, width, height, path);
  checkChunkCount(bytes, header, path);
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
      // The tile's place as its block names it, which tinyexr passes on unchecked.
      const int64_t x0 = int64_t(tile.offset_x) * header.tile_size_x, y0 = int64_t(tile.offset_y) * header.tile_size_y;
      if (x0 < 0 || y0 < 0 || x0 >= w || y0 >= h || tile.width < 1 || tile.height < 1 ||
          tile.width > header.tile_size_x || tile.height > header.tile_size_y) {
        throw std::runtime_error(path + ": OpenEXR tile (" + std::to_string(tile.offset_x) + ", " +
                                 std::to_string(tile.offset_y) + ") lies outside the data window");
      }
      place(tile.images, int(x0), int(y0), tile.width, tile.height);
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
