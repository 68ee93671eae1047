#pragma once
#include <string>

#include "app/args.hpp"
#include "core/builtin_scenes.hpp"

namespace pbr {

// The scene a `--scene` argument names: a built-in scene, or else an existing scene file (.json, .gltf, .glb),
// validated. Throws SceneError with a one-line message, or UsageError for --view-angle with a scene other than
// fresnel-floor.
Scene resolveScene(const std::string& nameOrPath, const SceneParams& params);

// --allow-outside-uris and --strict, taken by every command that loads scene files, and the scene parameters they
// set (the other parameters left at their defaults).
OptionSpec allowOutsideUrisOption();
OptionSpec strictOption();
SceneParams sceneFileParams(const Args& args);

}  // namespace pbr
