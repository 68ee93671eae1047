#pragma once
#include <string>

#include "app/args.hpp"
#include "core/builtin_scenes.hpp"

namespace pbr {

// Options several commands take with the same meaning and default; each command adds them to its table.
OptionSpec timingOption();       // --timing auto|gpu|serial
OptionSpec eglPlatformOption();  // --egl-platform auto|surfaceless|device
OptionSpec lightsOption(const std::string& defaultText);  // --lights N, for one scene
OptionSpec viewAngleOption();    // --view-angle DEG, fresnel-floor only

// `--lights` and `--view-angle` into the scene parameters, where given.
void applySceneShapeOptions(const Args& args, SceneParams& params);

}  // namespace pbr
