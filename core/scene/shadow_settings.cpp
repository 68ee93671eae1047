#include "core/scene/shadow_settings.hpp"

#include <stdexcept>
#include <string>

namespace pbr {

ShadowFilter parseShadowFilter(const std::string& name) {
  if (name == "hard") return ShadowFilter::Hard;
  if (name == "pcf3x3") return ShadowFilter::Pcf3x3;
  if (name == "poisson16") return ShadowFilter::Poisson16;
  throw std::invalid_argument("unknown shadow filter '" + name + "' (expected hard, pcf3x3 or poisson16)");
}

const char* toString(ShadowFilter filter) {
  switch (filter) {
    case ShadowFilter::Hard: return "hard";
    case ShadowFilter::Pcf3x3: return "pcf3x3";
    case ShadowFilter::Poisson16: return "poisson16";
  }
  return "?";
}

ShadowDraws parseShadowDraws(const std::string& name) {
  for (const ShadowDraws d : {ShadowDraws::Auto, ShadowDraws::PerView, ShadowDraws::PerLight}) {
    if (name == toString(d)) return d;
  }
  throw std::invalid_argument("unknown shadow draws '" + name + "' (expected auto, per-view or per-light)");
}

const char* toString(ShadowDraws draws) {
  switch (draws) {
    case ShadowDraws::Auto: return "auto";
    case ShadowDraws::PerView: return "per-view";
    case ShadowDraws::PerLight: return "per-light";
  }
  return "?";
}

const char* shadowFilterDefine(ShadowFilter filter) {
  switch (filter) {
    case ShadowFilter::Hard: return "SHADOW_FILTER_HARD";
    case ShadowFilter::Pcf3x3: return "SHADOW_FILTER_PCF3X3";
    case ShadowFilter::Poisson16: return "SHADOW_FILTER_POISSON16";
  }
  return "?";
}

namespace {

uint32_t log2Side(int size) {
  uint32_t bits = 0;
  while ((1 << (bits + 1)) <= size) ++bits;
  return bits;
}

}  // namespace

uint32_t lightShadowEntry(uint32_t firstView, int size, LightShadowKind kind) {
  const uint32_t flags = kind == LightShadowKind::Cube         ? kCubeShadow
                         : kind == LightShadowKind::SpotFrameX ? kShadowFrameX
                                                               : 0u;
  return (firstView + 1u) | log2Side(size) << 26 | flags;
}

uint32_t packShadowSquare(glm::ivec2 origin, int size) {
  return size > 0 ? uint32_t(origin.x) | uint32_t(origin.y) << 14 | log2Side(size) << 28 : 0u;
}

ShaderDefines shadowViewDefines() {
  return {{"SHADOW_BORDER_TEXELS", std::to_string(kShadowBorderTexels) + ".0"},
          {"SHADOW_NEAR_SCALE", std::to_string(kShadowNearScale)}};  // "0.000001": six decimals hold it
}

}  // namespace pbr
