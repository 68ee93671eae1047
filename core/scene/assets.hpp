#pragma once
#include <string>

namespace pbr {

// The shared asset folder: $PBR_ASSET_DIR, else the one configured at build time (<repo>/../shared/assets).
std::string assetDir();

// `relative` inside the asset folder; throws SceneError naming the full path when no such file exists.
std::string assetPath(const std::string& relative);

}  // namespace pbr
