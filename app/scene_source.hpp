#pragma once
#include <string>

#include "app/args.hpp"
#include "core/scene/builtin_scenes.hpp"

namespace pbr {

// The scene a `--scene` argument names: a built-in scene, or else an existing scene file (.json, .gltf, .glb),
// validated. Throws SceneError with a one-line message, or UsageError for --view-angle with a scene other than
// fresnel-floor.
Scene resolveScene(const std::string& nameOrPath, const SceneParams& params);
std::string builtinSceneList();  // "default, sphere-grid, ...", for help texts and messages

// The exposure a command's frames get once --exposure and --ev100 replace the scene's (Scene::displayExposure).
// --exposure auto meters each PBR frame (post/exposure_meter.hpp) unless the scene's camera states its exposure,
// which keeps priority (said in `note`); UsageError with --ev100, which sets what auto would meter.
struct ExposureChoice {
  float exposure = 1.0f;  // with autoExposure, what frames start from until one is metered
  bool autoExposure = false;
  std::string note;  // why --exposure auto does not apply; empty when it does or was not asked for
};
ExposureChoice applyExposureOptions(const Args& args, Scene& scene);

// --camera N|auto: one of the glTF cameras of the scene, or the framing of a model given alone.
void applyCameraOption(const Args& args, Scene& scene);

// --environment F.hdr|sky|none and --environment-intensity X, taken by the commands that show frames. Given,
// --environment decides alone: the loaders then add no default environment (defaultEnvironment says None), and
// applyEnvironmentOptions puts its choice in the loaded scene and scales whichever environment applies; UsageError
// for an intensity without an environment.
DefaultEnvironment defaultEnvironment(const Args& args);
void applyEnvironmentOptions(const Args& args, Scene& scene);

// The scene parameters --allow-outside-uris, --strict, --spot-share, and --gltf-scene, --animation and --time
// (which scene and moment of its glTF models a scene is drawn at, SceneParams::gltfSelection) set; the other
// parameters are left at their defaults.
SceneParams sceneFileParams(const Args& args);

}  // namespace pbr
