#pragma once
#include <string>

#include "core/scene/builtin_scenes.hpp"
#include "core/scene/camera.hpp"
#include "core/scene/scene.hpp"

namespace pbr {

// What the viewer shows, as far as a scene file can say it.
struct SceneSnapshot {
  const std::string& sceneName;  // the --scene the viewer loaded: a built-in name or a file
  const SceneParams& params;     // with the light count the viewer has now
  const Scene& scene;            // its lights at rest, its environment and exposure as the viewer has them
  const Camera& camera;          // the viewer's camera
  float displayExposure;         // what the post pass multiplies radiance by
};

// Writes a JSON scene that `pbr render --scene path` renders as the viewer shows `shot`, the lights at rest: the
// source file (a built-in's file, or a glTF model placed alone) with the camera, exposure, ambient and environment
// replaced, its relative paths made absolute so that the file may live anywhere, and the light count in
// random_lights. A built-in whose light count or view angle is a rule of its own (sphere-grid, light-wall, helmet,
// fresnel-floor) gets its lights listed instead. The file is read back and its lights compared with the shown
// ones: SceneError when they differ (a glTF model's own lights cannot be listed beside it) or it cannot be written.
void writeSceneSnapshot(const std::string& path, const SceneSnapshot& shot);

}  // namespace pbr
