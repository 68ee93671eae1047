#pragma once
#include <string>

#include "core/builtin_scenes.hpp"

namespace pbr {

// The scene a `--scene` argument names: a built-in scene, validated. Throws SceneError with a one-line message.
Scene resolveScene(const std::string& nameOrPath, const SceneParams& params);

}  // namespace pbr
