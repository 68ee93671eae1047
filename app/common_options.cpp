#include "app/common_options.hpp"

#include "core/context.hpp"

namespace pbr {

OptionSpec timingOption() {
  return {"--timing", "MODE", "auto (serial on a CPU rasterizer, else gpu), gpu (timer queries) or serial (glFinish "
                              "+ CPU clock)", "auto", ""};
}

OptionSpec eglPlatformOption() {
  return {"--egl-platform", "P", "auto, surfaceless (Mesa) or device (first hardware device)",
          toString(EglPlatform::Auto), ""};
}

OptionSpec lightsOption(const std::string& defaultText) {
  return {"--lights", "N", "number of point lights", "", defaultText};
}

OptionSpec viewAngleOption() {
  return {"--view-angle", "DEG", "fresnel-floor: angle between the floor normal and the view", "",
          "as the scene file places it, 40"};
}

void applySceneShapeOptions(const Args& args, SceneParams& params) {
  if (args.has("--lights")) params.lights = args.getInt("--lights", 0, 1 << 20);
  if (args.has("--view-angle")) params.viewAngleDeg = args.getFloat("--view-angle", 0.0f, 89.0f);
}

}  // namespace pbr
