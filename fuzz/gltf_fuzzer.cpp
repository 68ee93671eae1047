// glTF 2.0 models (core/scene/gltf_file.*, core/scene/gltf_loader.* and what they call: accessors, materials, textures):
// appendGltf on a .gltf or .glb file, told apart by its magic as the loader does. Buffers and images must be data
// URIs or, in a GLB, buffer views: the input is the only file. Rejections throw SceneError; any other exception
// escapes and is reported as a crash.
#include <cstddef>
#include <cstdint>
#include <stdexcept>

#include "core/scene/gltf_loader.hpp"
#include "fuzz/temp_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = pbr::fuzz::writeTempInput("model.gltf", data, size);
  try {
    pbr::Scene scene;
    pbr::appendGltf(scene, path);
  } catch (const std::runtime_error&) {
  }
  return 0;
}
