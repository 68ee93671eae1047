// Texture images (core/scene/image.*: readPng, which scene files' base_color_texture goes through): stb_image's PNG and
// JPEG decoders and the message on failure. glTF images reach the same decoder through gltf_fuzzer. Rejections
// throw std::runtime_error; any other exception escapes and is reported as a crash.
#include <cstddef>
#include <cstdint>
#include <stdexcept>

#include "core/scene/image.hpp"
#include "fuzz/temp_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = pbr::fuzz::writeTempInput("texture.png", data, size);
  try {
    pbr::readPng(path);
  } catch (const std::runtime_error&) {
  }
  return 0;
}
