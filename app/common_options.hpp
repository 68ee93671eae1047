#pragma once
#include <string>

#include "app/args.hpp"
#include "core/scene/builtin_scenes.hpp"
#include "core/scene/shadow_settings.hpp"
#include "core/scene/tone_curve.hpp"
#include "core/scene/transparency.hpp"

namespace pbr {

// Readers of options several commands take (their rows are in app/option_table.cpp).

// --shadows, --shadow-filter and --shadow-atlas as settings.
ShadowSettings readShadowSettings(const Args& args);
int readShadowAtlas(const Args& args);  // a power of two, checked
bool readShadowCache(const Args& args);  // "on" or "off"
Transparency readTransparency(const Args& args);  // --transparency
ToneCurve readToneCurve(const Args& args);        // --tonemap

// `--lights` and `--view-angle` into the scene parameters, where given.
void applySceneShapeOptions(const Args& args, SceneParams& params);

}  // namespace pbr
