#include "app/common_options.hpp"

namespace pbr {

ShadowSettings readShadowSettings(const Args& args) {
  ShadowSettings s;
  s.mode = parseShadowMode(args.get("--shadows"));
  s.filter = parseShadowFilter(args.get("--shadow-filter"));
  s.atlasSize = readShadowAtlas(args);
  s.cache = readShadowCache(args);
  return s;
}

bool readShadowCache(const Args& args) {
  const std::string value = args.get("--shadow-cache");
  if (value != "on" && value != "off") throw UsageError("--shadow-cache " + value + ": expected on or off");
  return value == "on";
}

int readShadowAtlas(const Args& args) {
  const int size = args.getInt("--shadow-atlas", kMinShadowAtlas, kMaxShadowAtlas);
  if ((size & (size - 1)) != 0) {
    throw UsageError("--shadow-atlas " + std::to_string(size) + ": expected a power of two (256 to 16384)");
  }
  return size;
}

Transparency readTransparency(const Args& args) { return parseTransparency(args.get("--transparency")); }

ToneCurve readToneCurve(const Args& args) { return parseToneCurve(args.get("--tonemap")); }

void applySceneShapeOptions(const Args& args, SceneParams& params) {
  if (args.has("--lights")) params.lights = args.getInt("--lights", 0, 1 << 20);
  if (args.has("--view-angle")) params.viewAngleDeg = args.getFloat("--view-angle", 0.0f, 89.0f);
}

}  // namespace pbr
