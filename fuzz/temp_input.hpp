#pragma once
#include <cstddef>
#include <cstdint>
#include <string>

namespace pbr::fuzz {

// The loaders read files by path, so each input is written to a file first. The file lives in a folder of its own
// per process, in memory (/dev/shm) where there is one, or in $PBR_FUZZ_TMP when set; the folder is removed at
// exit. `name` gives the extension the loader dispatches on (scene.json, model.gltf, ...). Returns the path.
std::string writeTempInput(const std::string& name, const uint8_t* data, size_t size);

}  // namespace pbr::fuzz
