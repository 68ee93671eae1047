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
};

// True when the bytes start with the GLB magic "glTF".
bool hasGlbMagic(const std::string& bytes);

// Checks the header and chunk layout as the glTF 2.0 specification states it. Throws SceneError
// "PATH: GLB header: ..." or "PATH: GLB chunk 0: ..." naming what is wrong and the values found.
GlbChunks readGlbChunks(const std::string& bytes, const std::string& path);

}  // namespace pbr
