#include "core/scene/assets.hpp"

#include <cstdlib>
#include <filesystem>

#include "core/scene/scene.hpp"

namespace pbr {

std::string assetDir() {
  const char* env = std::getenv("PBR_ASSET_DIR");
  return env && *env ? env : PBR_ASSET_DIR;
}

std::string assetPath(const std::string& relative) {
  const std::string path = (std::filesystem::path(assetDir()) / relative).string();
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    throw SceneError(path + ": asset not found (PBR_ASSET_DIR names the shared assets folder)");
  }
  return path;
}

}  // namespace pbr
