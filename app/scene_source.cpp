#include "app/scene_source.hpp"

#include <filesystem>

#include "app/args.hpp"
#include "core/scene_json.hpp"

namespace pbr {

OptionSpec allowOutsideUrisOption() {
  return {"--allow-outside-uris", "",
          "let glTF models read buffers and images outside their own folder (refused by default)"};
}

OptionSpec strictOption() {
  return {"--strict", "", "refuse a scene file holding a key the reader does not know (a misspelt field) instead of "
                          "warning about it"};
}

SceneParams sceneFileParams(const Args& args) {
  SceneParams params;
  params.uris = {args.has("--allow-outside-uris")};
  params.strictKeys = args.has("--strict");
  return params;
}

Scene resolveScene(const std::string& nameOrPath, const SceneParams& params) {
  if (params.viewAngleDeg && nameOrPath != "fresnel-floor") {
    throw UsageError("--view-angle applies only to --scene fresnel-floor");
  }
  Scene scene;
  if (isBuiltinScene(nameOrPath)) {
    scene = makeBuiltinScene(nameOrPath, params);
  } else if (std::filesystem::exists(nameOrPath)) {
    scene = loadSceneFile(nameOrPath, params.lights.value_or(-1), params.uris, params.strictKeys);
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
