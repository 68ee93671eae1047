#pragma once
#include <string>

#include "app/args.hpp"
#include "core/scene/builtin_scenes.hpp"
#include "core/scene/shadow_settings.hpp"
#include "core/scene/tone_curve.hpp"
#include "core/scene/transparency.hpp"

namespace pbr {

// Options several commands take with the same meaning and default; each command adds them to its table.
OptionSpec timingOption();       // --timing auto|gpu|serial
OptionSpec eglPlatformOption();  // --egl-platform auto|surfaceless|device
OptionSpec lightsOption(const std::string& defaultText);  // --lights N, for one scene
OptionSpec viewAngleOption();    // --view-angle DEG, fresnel-floor only

OptionSpec shadowModeOption();    // --shadows none|on|auto
OptionSpec shadowFilterOption();  // --shadow-filter hard|pcf3x3|poisson16
OptionSpec shadowAtlasOption();   // --shadow-atlas SIZE
// The three shadow options as settings.
ShadowSettings readShadowSettings(const Args& args);

OptionSpec transparencyOption();  // --transparency sorted|oit
Transparency readTransparency(const Args& args);
OptionSpec toneMapOption();  // --tonemap aces-hill|...
ToneCurve readToneCurve(const Args& args);

// `--lights` and `--view-angle` into the scene parameters, where given.
void applySceneShapeOptions(const Args& args, SceneParams& params);

}  // namespace pbr
