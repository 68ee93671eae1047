#include "core/scene/glb_container.hpp"

#include <cstdint>
#include <cstring>

#include "core/scene/scene.hpp"

namespace pbr {

namespace {

constexpr uint32_t kJsonChunk = 0x4E4F534A;  // "JSON"
constexpr uint32_t kBinChunk = 0x004E4942;   // "BIN\0"

uint32_t word(const std::string& bytes, std::size_t at) {
  unsigned char b[4];
  std::memcpy(b, bytes.data() + at, 4);
  return uint32_t(b[0]) | uint32_t(b[1]) << 8 | uint32_t(b[2]) << 16 | uint32_t(b[3]) << 24;  // little endian
}

// Four bytes as text, unprintable ones as \xNN.
std::string printable(const std::string& bytes, std::size_t at) {
  std::string out;
  for (std::size_t i = at; i < at + 4 && i < bytes.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(bytes[i]);
    if (c >= 0x20 && c < 0x7f) {
      out += static_cast<char>(c);
    } else {
      const char* hex = "0123456789abcdef";
      out += std::string("\\x") + hex[c >> 4] + hex[c & 15];
    }
  }
  return "\"" + out + "\"";
}

}  // namespace

bool hasGlbMagic(const std::string& bytes) { return bytes.compare(0, 4, "glTF") == 0; }

GlbChunks readGlbChunks(const std::string& bytes, const std::string& path) {
  const auto fail = [&](const std::string& where, const std::string& what) {
    throw SceneError(path + ": GLB " + where + ": " + what);
  };
  const std::string size = std::to_string(bytes.size());
  if (bytes.size() < 20) fail("header", "the file has " + size + " bytes, fewer than a header and a chunk header");
  if (!hasGlbMagic(bytes)) fail("header", "magic is " + printable(bytes, 0) + ", expected \"glTF\"");
  if (word(bytes, 4) != 2) fail("header", "version is " + std::to_string(word(bytes, 4)) + ", expected 2");
  if (word(bytes, 8) != bytes.size()) {
    fail("header", "length is " + std::to_string(word(bytes, 8)) + ", but the file has " + size + " bytes");
  }
  const uint64_t jsonLength = word(bytes, 12), jsonEnd = 20 + jsonLength;
  if (word(bytes, 16) != kJsonChunk) fail("chunk 0", "type is " + printable(bytes, 16) + ", expected \"JSON\"");
  if (jsonEnd > bytes.size()) {
    fail("chunk 0", "length " + std::to_string(jsonLength) + " runs past the end of the " + size + "-byte file");
  }
  if (jsonLength % 4 != 0) fail("chunk 0", "length " + std::to_string(jsonLength) + " is not a multiple of 4");
  GlbChunks chunks;
  chunks.json = bytes.substr(20, jsonLength);
  if (jsonEnd == bytes.size()) return chunks;
  if (jsonEnd + 8 > bytes.size()) fail("chunk 1", "its 8-byte header runs past the end of the file");
  const uint64_t binLength = word(bytes, jsonEnd);
  if (word(bytes, jsonEnd + 4) != kBinChunk) {
    fail("chunk 1", "type is " + printable(bytes, jsonEnd + 4) + ", expected \"BIN\\x00\"");
  }
  if (jsonEnd + 8 + binLength > bytes.size()) {
    fail("chunk 1", "length " + std::to_string(binLength) + " runs past the end of the " + size + "-byte file");
  }
  if (binLength % 4 != 0) fail("chunk 1", "length " + std::to_string(binLength) + " is not a multiple of 4");
  chunks.hasBin = true;
  chunks.binLength = binLength;
  chunks.binOffset = jsonEnd + 8;
  return chunks;
}

std::string withGlbJson(const std::string& bytes, const GlbChunks& chunks, const std::string& json) {
  const auto put32 = [](std::string& out, uint64_t v) {
    for (int i = 0; i < 4; ++i) out.push_back(static_cast<char>((v >> (8 * i)) & 0xFF));
  };
  std::string text = json;
  while (text.size() % 4 != 0) text.push_back(' ');
  const size_t total = 12 + 8 + text.size() + (chunks.hasBin ? 8 + chunks.binLength : 0);
  std::string out = "glTF";
  put32(out, 2);
  put32(out, total);
  put32(out, text.size());
  out += "JSON";
  out += text;
  if (chunks.hasBin) {
    put32(out, chunks.binLength);
    out += "BIN";
    out.push_back('\0');
    out.append(bytes, chunks.binOffset, chunks.binLength);
  }
  return out;
}

}  // namespace pbr
