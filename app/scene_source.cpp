#include "app/scene_source.hpp"

#include <filesystem>

#include "app/args.hpp"
#include "core/exposure.hpp"
#include "core/scene_json.hpp"

namespace pbr {

OptionSpec allowOutsideUrisOption() {
  return {"--allow-outside-uris", "",
          "let glTF models read buffers and images outside their own folder (refused by default)"};
}

UriPolicy uriPolicy(const Args& args) { return {args.has("--allow-outside-uris")}; }

OptionSpec ev100Option() {
  return {"--ev100", "EV",
          "physical exposure: the camera's exposure value at ISO 100 (sunny day about 15, indoors 6-8), scaling "
          "radiance by 1 / (1.2 2^EV) before --exposure (default: the scene camera's, or none)"};
}

float applyExposureOptions(const Args& args, Scene& scene) {
  if (args.has("--ev100")) scene.ev100 = args.getFloat("--ev100", 0.0f, -kMaxEv100, kMaxEv100);
  scene.exposure = args.getFloat("--exposure", scene.exposure, 0.0f, 1e6f);
  return scene.displayExposure();
}

Scene resolveScene(const std::string& nameOrPath, const SceneParams& params) {
  if (params.viewAngleDeg && nameOrPath != "fresnel-floor") {
    throw UsageError("--view-angle applies only to --scene fresnel-floor");
  }
  Scene scene;
  if (isBuiltinScene(nameOrPath)) {
    scene = makeBuiltinScene(nameOrPath, params);
  } else if (std::filesystem::exists(nameOrPath)) {
    scene = loadSceneFile(nameOrPath, params.lights.value_or(-1), params.uris);
  } else {
    std::string names;
    for (const std::string& n : builtinSceneNames()) names += (names.empty() ? "" : ", ") + n;
    throw SceneError("unknown scene '" + nameOrPath + "': not a built-in scene (" + names +
                     ") and no such file exists");
  }
  validateScene(scene, nameOrPath);
  return scene;
}

}  // namespace pbr
