#include "app/scene_source.hpp"

#include <filesystem>

#include "app/args.hpp"
#include "core/scene/exposure.hpp"
#include "core/scene/messages.hpp"
#include "core/scene/scene_json.hpp"

namespace pbr {

SceneParams sceneFileParams(const Args& args) {
  SceneParams params;
  params.uris = {args.has("--allow-outside-uris"), args.has("--strict")};
  params.strictKeys = args.has("--strict");
  if (args.has("--spot-share")) params.spotShare = args.getFloat("--spot-share", 0.0f, 1.0f);
  if (args.has("--gltf-scene")) params.gltfSelection.scene = args.getInt("--gltf-scene", 0, 1 << 20);
  if (args.has("--animation")) params.gltfSelection.animation = args.get("--animation");
  if (args.has("--time")) params.gltfSelection.time = args.getFloat("--time", -1e9f, 1e9f);
  return params;
}

void applyCameraOption(const Args& args, Scene& scene) {
  if (!args.has("--camera")) return;
  const std::string choice = args.get("--camera");
  if (choice == "auto") {
    if (!scene.framedCamera) throw UsageError("--camera auto applies to a .gltf or .glb given alone as --scene");
    scene.camera = *scene.framedCamera;
    return;
  }
  if (scene.cameras.empty()) {
    throw UsageError("--camera " + choice + ": the scene has no glTF camera (auto frames a model given alone)");
  }
  const int index = args.getInt("--camera", 0, static_cast<int>(scene.cameras.size()) - 1);
  scene.camera = scene.cameras[static_cast<size_t>(index)];
}

DefaultEnvironment defaultEnvironment(const Args& args) {
  return args.has("--environment") ? DefaultEnvironment::None : DefaultEnvironment::Sky;
}

// --environment sets intensity 1 and no rotation.
void applyEnvironmentOptions(const Args& args, Scene& scene) {
  if (args.has("--environment")) {
    const std::string source = args.get("--environment");
    if (source.empty()) throw UsageError("--environment needs a .hdr file, \"sky\" or \"none\"");
    if (source == "none") {
      scene.environment.reset();
    } else {
      scene.environment = EnvironmentDesc{};
      if (source != "sky") scene.environment->file = source;
    }
  }
  if (args.has("--environment-intensity")) {
    if (!scene.environment) {
      throw UsageError("--environment-intensity needs an environment (--environment or the scene's)");
    }
    scene.environment->intensity = args.getFloat("--environment-intensity", 0.0f, 1e6f);
  }
}

ExposureChoice applyExposureOptions(const Args& args, Scene& scene) {
  ExposureChoice choice;
  choice.autoExposure = args.get("--exposure") == "auto";
  if (choice.autoExposure && args.has("--ev100")) {
    throw UsageError("--exposure auto meters the frame's exposure and --ev100 sets it: give one of them");
  }
  if (args.has("--ev100")) {
    scene.ev100 = args.getFloat("--ev100", -kMaxEv100, kMaxEv100);
    scene.ev100Metered = false;
  }
  if (args.has("--exposure") && !choice.autoExposure) {
    scene.exposure = args.getFloat("--exposure", 0.0f, kMaxExposure);
  }
  if (choice.autoExposure && scene.ev100 && !scene.ev100Metered) {
    choice.autoExposure = false;
    choice.note = "the scene's camera sets EV100 " + fixedDecimals(*scene.ev100, 2) +
                  ", which keeps priority over --exposure auto (--ev100 sets another)";
  }
  choice.exposure = scene.displayExposure();
  return choice;
}

std::string builtinSceneList() {
  std::string names;
  for (const std::string& n : builtinSceneNames()) names += (names.empty() ? "" : ", ") + n;
  return names;
}

Scene resolveScene(const std::string& nameOrPath, const SceneParams& params) {
  if (params.viewAngleDeg && nameOrPath != "fresnel-floor") {
    throw UsageError("--view-angle applies only to --scene fresnel-floor");
  }
  Scene scene;
  if (isBuiltinScene(nameOrPath)) {
    scene = makeBuiltinScene(nameOrPath, params);
  } else if (std::filesystem::exists(nameOrPath)) {
    scene = loadSceneFile(nameOrPath, params.lights.value_or(-1), params.uris, params.strictKeys,
                          params.defaultEnvironment, params.spotShare, params.gltfSelection);
  } else {
    throw SceneError("unknown scene '" + nameOrPath + "': not a built-in scene (" + builtinSceneList() +
                     ") and no such file exists");
  }
  // A scene without glTF models has nothing the glTF options could choose: refused rather than ignored.
  const GltfSelection& g = params.gltfSelection;
  if ((g.scene || g.animated()) && scene.gltfFiles.empty()) {
    throw UsageError(std::string(g.scene ? "--gltf-scene" : g.animation ? "--animation" : "--time") +
                     " applies only to scenes with glTF models");
  }
  validateScene(scene, nameOrPath);
  return scene;
}

}  // namespace pbr
