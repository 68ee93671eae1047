#include "app/scene_source.hpp"

#include <filesystem>

#include "app/args.hpp"
#include "core/scene_json.hpp"

namespace pbr {

OptionSpec allowOutsideUrisOption() {
  return {"--allow-outside-uris", "",
          "let glTF models read buffers and images outside their own folder (refused by default)"};
}

UriPolicy uriPolicy(const Args& args) { return {args.has("--allow-outside-uris")}; }

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
