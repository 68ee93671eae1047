// Scene files (core/scene/scene_json.*, core/scene/json_file.*): the whole loadSceneFile path, with the glTF models and PNG
// textures a scene names. A rejected file throws SceneError (a std::runtime_error); any other exception escapes
// and is reported as a crash, as it would abort the renderer's message for the file.
#include <cstddef>
#include <cstdint>
#include <stdexcept>

#include "core/scene/scene_json.hpp"
#include "fuzz/temp_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = pbr::fuzz::writeTempInput("scene.json", data, size);
  try {
    pbr::loadSceneFile(path);
  } catch (const std::runtime_error&) {
  }
  return 0;
}
