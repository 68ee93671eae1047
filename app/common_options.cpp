#include "app/common_options.hpp"

#include "core/io/context_info.hpp"

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

OptionSpec shadowModeOption() {
  return {"--shadows", "none|on|auto",
          "which lights cast shadows: auto as the scene says (glTF lights, JSON spot and directional lights, and "
          "those with \"shadows\": true), on every light, none", toString(ShadowSettings{}.mode), ""};
}

OptionSpec shadowFilterOption() {
  return {"--shadow-filter", "F",
          "shadow-map filter: hard (one comparison), pcf3x3 (3x3 bilinear comparisons, a 4x4-texel tent) or "
          "poisson16 (16 bilinear comparisons on a 1.5-texel disc)", toString(ShadowSettings{}.filter), ""};
}

OptionSpec shadowAtlasOption() {
  return {"--shadow-atlas", "SIZE",
          "side of the shadow atlas in texels, a power of two from 256 to 16384 (4 bytes a texel: 4096 is 64 MiB, "
          "8192 256 MiB); allocated only when a light casts", std::to_string(ShadowSettings{}.atlasSize), ""};
}

ShadowSettings readShadowSettings(const Args& args) {
  ShadowSettings s;
  s.mode = parseShadowMode(args.get("--shadows"));
  s.filter = parseShadowFilter(args.get("--shadow-filter"));
  s.atlasSize = args.getInt("--shadow-atlas", kMinShadowAtlas, kMaxShadowAtlas);
  if ((s.atlasSize & (s.atlasSize - 1)) != 0) {
    throw UsageError("--shadow-atlas " + std::to_string(s.atlasSize) + ": expected a power of two (256 to 16384)");
  }
  return s;
}

OptionSpec transparencyOption() {
  return {"--transparency", "T",
          "how BLEND materials composite: sorted (back to front by their bounds, Porter-Duff over), oit (weighted "
          "blended order-independent transparency, one pass in any order; 18 bytes per pixel) or exact (every "
          "fragment in a list per pixel, composited in depth order; room for 8 a pixel, 132 bytes per pixel)",
          toString(Transparency::Sorted), ""};
}

Transparency readTransparency(const Args& args) { return parseTransparency(args.get("--transparency")); }

OptionSpec toneMapOption() {
  return {"--tonemap", "CURVE",
          std::string("the PBR display transform's tone curve after exposure: ") + toneCurveNames() +
              " (aces-hill: Hill's ACES fit, the study's curve; aces-narkowicz: Narkowicz's fit; khronos-neutral: "
              "Khronos PBR Neutral, glTF-Sample-Viewer's default; agx: Blender's AgX Base; reinhard: white point "
              "4; exponential: 1 - e^-x, the seeds'; linear: a clamp)",
          toString(ToneCurve::AcesHill), ""};
}

ToneCurve readToneCurve(const Args& args) { return parseToneCurve(args.get("--tonemap")); }

void applySceneShapeOptions(const Args& args, SceneParams& params) {
  if (args.has("--lights")) params.lights = args.getInt("--lights", 0, 1 << 20);
  if (args.has("--view-angle")) params.viewAngleDeg = args.getFloat("--view-angle", 0.0f, 89.0f);
}

}  // namespace pbr
