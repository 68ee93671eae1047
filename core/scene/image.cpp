#include "core/scene/image.hpp"

#include <stb_image.h>
#include <webp/decode.h>

#include <climits>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>
#include <optional>
#include <stdexcept>
#include <vector>

#include "core/scene/input_file.hpp"

namespace pbr {

bool overImageLimit(int64_t width, int64_t height) {
  return width > kMaxImageSide || height > kMaxImageSide || width * height > kMaxImagePixels;
}

std::string imageLimitText(int64_t width, int64_t height) {
  return std::to_string(width) + "x" + std::to_string(height) + " pixels, over the image limit (" +
         std::to_string(kMaxImageSide) + " a side, " + std::to_string(kMaxImagePixels) + " pixels in all)";
}

bool overEnvironmentLimit(int64_t width, int64_t height) { return width * height > kMaxImagePixels; }

std::string environmentLimitText(int64_t width, int64_t height) {
  return std::to_string(width) + "x" + std::to_string(height) + " is " + std::to_string(width * height) +
         " pixels, over the limit of " + std::to_string(kMaxImagePixels) + " (1 GiB as float RGBA)";
}

ImageRgba8 readPng(const std::string& path) {
  const std::string bytes = readInputFile(path);
  return decodeImage(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(), path);
}

std::string decoderFailureReason() {
  const char* reason = stbi_failure_reason();
  return reason && *reason ? std::string(": ") + reason : std::string();
}

namespace {

bool isPng(const unsigned char* b, size_t size) {
  static const unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  return size >= 8 && std::memcmp(b, signature, 8) == 0;
}

// A start-of-image marker after one or more 0xFF bytes, as stb_image takes it.
bool isJpeg(const unsigned char* b, size_t size) {
  size_t start = 0;
  while (start < size && b[start] == 0xFF) ++start;
  return start > 0 && start < size && b[start] == 0xD8;
}

// Returns what in a JPEG's marker segments stb_image would mishandle, or "" (also for data that is no JPEG). Walks
// the segments, skipping entropy-coded data, stuffed bytes and restart markers; stb takes any run of 0xFF fill
// bytes before a marker, the start-of-image marker included. Two things stb does not check itself:
// - it builds each Huffman table into fixed arrays of 257 entries without checking that the 16 code counts sum to
//   at most 256 (ITU T.81 B.2.4.2), so a corrupt DHT segment writes past them;
// - a scan may name a Huffman table no DHT segment defined (T.81 B.2.3 requires it defined), and stb then decodes
//   with that table's uninitialised memory, indexing its symbol array anywhere.
std::string jpegSegmentProblem(const unsigned char* b, size_t size) {
  if (!isJpeg(b, size)) return "";
  size_t start = 0;
  while (b[start] == 0xFF) ++start;  // to the start-of-image marker
  bool defined[2][4] = {};  // [class: 0 DC, 1 AC][table id], as DHT segments so far define them
  bool progressive = false;
  for (size_t pos = start + 1; pos + 1 < size;) {
    if (b[pos] != 0xFF) {
      ++pos;
      continue;
    }
    const unsigned marker = b[pos + 1];
    if (marker == 0x00 || marker == 0xFF) {  // a stuffed 0xFF in entropy-coded data, or fill
      ++pos;
      continue;
    }
    if ((marker >= 0xD0 && marker <= 0xD8) || marker == 0x01) {  // RSTn, SOI, TEM: no length
      pos += 2;
      continue;
    }
    if (marker == 0xD9) return "";  // EOI
    if (pos + 4 > size) return "truncated JPEG marker segment";
    const size_t length = size_t(b[pos + 2]) << 8 | b[pos + 3];
    if (length < 2 || pos + 2 + length > size) return "truncated JPEG marker segment";
    const size_t end = pos + 2 + length;
    if (marker == 0xC2) progressive = true;  // the one progressive frame type stb decodes
    if (marker == 0xC4) {
      for (size_t table = pos + 4; table < end;) {
        if (table + 17 > end) return "truncated JPEG Huffman table";
        size_t codes = 0;
        for (int i = 1; i <= 16; ++i) codes += b[table + i];
        if (codes > 256) return "a JPEG Huffman table with " + std::to_string(codes) + " codes (at most 256)";
        const unsigned tableClass = b[table] >> 4, id = b[table] & 15u;
        if (tableClass <= 1 && id <= 3) defined[tableClass][id] = true;  // stb refuses other classes and ids
        table += 17 + codes;
        if (table > end) return "a JPEG Huffman table longer than its segment";
      }
    }
    if (marker == 0xDA) {  // start of scan: Ns, Ns x (Cs, Td:Ta), Ss, Se, Ah:Al (T.81 B.2.3)
      const size_t components = pos + 4 < end ? b[pos + 4] : 0;
      if (pos + 5 + 2 * components + 3 > end) return "truncated JPEG scan header";
      const unsigned spectralStart = b[pos + 5 + 2 * components], approximationHigh = b[pos + 7 + 2 * components] >> 4;
      // Which tables stb decodes with: both in a sequential scan; in a progressive one the DC table only in a DC
      // scan's first pass, the AC table in every AC scan.
      const bool usesDc = !progressive || (spectralStart == 0 && approximationHigh == 0);
      const bool usesAc = !progressive || spectralStart != 0;
      for (size_t c = 0; c < components; ++c) {
        const unsigned dc = b[pos + 6 + 2 * c] >> 4, ac = b[pos + 6 + 2 * c] & 15u;
        if (usesDc && dc <= 3 && !defined[0][dc])
          return "a JPEG scan uses DC Huffman table " + std::to_string(dc) + ", which no DHT segment defines";
        if (usesAc && ac <= 3 && !defined[1][ac])
          return "a JPEG scan uses AC Huffman table " + std::to_string(ac) + ", which no DHT segment defines";
      }
    }
    pos = end;
  }
  return "";
}

// A PNG chunk whose declared length runs past the end of the file: stb_image grows its data buffer to the declared
// length, doubling, before it finds the bytes missing, so a few hundred bytes can ask for gigabytes. Empty when
// every chunk fits (or the data is no PNG).
std::string pngChunkProblem(const unsigned char* b, size_t size) {
  if (!isPng(b, size)) return {};
  size_t pos = 8;
  while (pos + 12 <= size) {
    const size_t length = size_t(b[pos]) << 24 | size_t(b[pos + 1]) << 16 | size_t(b[pos + 2]) << 8 | b[pos + 3];
    if (length > size - pos - 12) {
      return "PNG chunk at byte " + std::to_string(pos) + " declares " + std::to_string(length) +
             " bytes, past the end of the data (" + std::to_string(size) + " bytes)";
    }
    pos += 12 + length;
  }
  return {};
}

// An empty IDAT chunk is legal PNG, but stb_image copies it (memcpy of 0 bytes) into a data buffer it has not
// allocated yet when it comes first, which is undefined behaviour. Returns the file without its empty IDAT chunks,
// or nothing when it has none (or is no PNG). Every chunk fits (pngChunkProblem).
std::optional<std::vector<unsigned char>> withoutEmptyPngData(const unsigned char* b, size_t size) {
  if (!isPng(b, size)) return std::nullopt;
  std::vector<unsigned char> kept(b, b + 8);
  bool dropped = false;
  size_t pos = 8;
  while (pos + 12 <= size) {
    const size_t length = size_t(b[pos]) << 24 | size_t(b[pos + 1]) << 16 | size_t(b[pos + 2]) << 8 | b[pos + 3];
    if (length > size - pos - 12) break;
    const bool emptyData = length == 0 && std::memcmp(b + pos + 4, "IDAT", 4) == 0;
    if (!emptyData) kept.insert(kept.end(), b + pos, b + pos + 12 + length);
    dropped = dropped || emptyData;
    pos += 12 + length;
  }
  if (!dropped) return std::nullopt;
  kept.insert(kept.end(), b + pos, b + size);
  return kept;
}

bool isWebp(const unsigned char* b, size_t size) {
  return size >= 12 && std::memcmp(b, "RIFF", 4) == 0 && std::memcmp(b + 8, "WEBP", 4) == 0;
}


// WebP (EXT_texture_webp) through libwebp: the header's size checked against the limits before the decoder
// allocates, as for stb's formats.
ImageRgba8 decodeWebp(const unsigned char* bytes, size_t size, const std::string& name) {
  int w = 0, h = 0;
  if (!WebPGetInfo(bytes, size, &w, &h)) {
    throw std::runtime_error(name + ": cannot decode image: not a valid WebP file");
  }
  if (overImageLimit(w, h)) {
    throw std::runtime_error(name + ": cannot decode image: " + imageLimitText(w, h));
  }
  std::unique_ptr<uint8_t, void (*)(void*)> data(WebPDecodeRGBA(bytes, size, &w, &h), WebPFree);
  if (!data) throw std::runtime_error(name + ": cannot decode image: corrupt WebP data");
  ImageRgba8 img{w, h, {}};
  img.pixels.assign(data.get(), data.get() + size_t(w) * size_t(h) * 4);
  return img;
}

}  // namespace

const char* imageMimeType(const unsigned char* bytes, size_t size) {
  return isPng(bytes, size) ? "image/png" : isJpeg(bytes, size) ? "image/jpeg" : isWebp(bytes, size) ? "image/webp"
                                                                                                   : nullptr;
}

ImageRgba8 decodeImage(const unsigned char* bytes, size_t size, const std::string& name) {
  if (size == 0) throw std::runtime_error(name + ": cannot decode image: no data");
  if (size > static_cast<size_t>(INT_MAX)) throw std::runtime_error(name + ": cannot decode image: over 2 GiB");
  if (isWebp(bytes, size)) return decodeWebp(bytes, size, name);
  // stb_image reads more formats than textures may be (Radiance, PSD, BMP, GIF, TGA, PNM), some of them with
  // endless loops on corrupt input: only PNG and JPEG reach it.
  if (!isPng(bytes, size) && !isJpeg(bytes, size)) {
    throw std::runtime_error(name + ": cannot decode image: not a PNG, JPEG or WebP image");
  }
  const std::string jpegProblem = jpegSegmentProblem(bytes, size);
  if (!jpegProblem.empty()) throw std::runtime_error(name + ": cannot decode image: " + jpegProblem);
  const std::string pngProblem = pngChunkProblem(bytes, size);
  if (!pngProblem.empty()) throw std::runtime_error(name + ": cannot decode image: " + pngProblem);
  const std::optional<std::vector<unsigned char>> png = withoutEmptyPngData(bytes, size);
  if (png) {
    bytes = png->data();
    size = png->size();
  }
  // The header alone sets what the decoder allocates: a few hundred bytes may declare gigapixels. A texture
  // larger than this could not be uploaded anyway (GL_MAX_TEXTURE_SIZE is 16384 on llvmpipe).
  int declaredW = 0, declaredH = 0, declaredN = 0;
  if (stbi_info_from_memory(bytes, static_cast<int>(size), &declaredW, &declaredH, &declaredN) &&
      overImageLimit(declaredW, declaredH)) {
    throw std::runtime_error(name + ": cannot decode image: " + imageLimitText(declaredW, declaredH));
  }
  int w = 0, h = 0, n = 0;
  std::unique_ptr<stbi_uc, void (*)(void*)> data(
      stbi_load_from_memory(bytes, static_cast<int>(size), &w, &h, &n, 4), stbi_image_free);
  if (!data) throw std::runtime_error(name + ": cannot decode image" + decoderFailureReason());
  ImageRgba8 img{w, h, {}};
  img.pixels.assign(data.get(), data.get() + static_cast<size_t>(w) * static_cast<size_t>(h) * 4);
  return img;
}


}  // namespace pbr
