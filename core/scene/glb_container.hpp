#pragma once
#include <cstddef>
#include <string>

namespace pbr {

// The chunks of a binary glTF (.glb): a 12-byte header ("glTF", version 2, total length), a JSON chunk and an
// optional BIN chunk, each an 8-byte header (length, type) and data padded to 4 bytes.
struct GlbChunks {
  std::string json;
  bool hasBin = false;
  std::size_t binLength = 0;
  std::size_t binOffset = 0;  // where the BIN chunk's data starts in the file
};

// A GLB of `json` and the BIN chunk of `bytes` (laid out as `chunks` says), as the specification lays one out: the
// JSON padded with spaces, each chunk to 4 bytes.
std::string withGlbJson(const std::string& bytes, const GlbChunks& chunks, const std::string& json);

// True when the bytes start with the GLB magic "glTF".
bool hasGlbMagic(const std::string& bytes);

// Checks the header and chunk layout as the glTF 2.0 specification states it. Throws SceneError
// "PATH: GLB header: ..." or "PATH: GLB chunk 0: ..." naming what is wrong and the values found.
GlbChunks readGlbChunks(const std::string& bytes, const std::string& path);

}  // namespace pbr
