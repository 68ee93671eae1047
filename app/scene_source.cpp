#include "app/scene_source.hpp"

namespace pbr {

Scene resolveScene(const std::string& nameOrPath, const SceneParams& params) {
  Scene scene = makeBuiltinScene(nameOrPath, params);
  validateScene(scene, nameOrPath);
  return scene;
}

}  // namespace pbr
