#include "core/shadow_maps.hpp"

#include <stdexcept>

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

const char* shadowFilterDefine(ShadowFilter filter) {
  switch (filter) {
    case ShadowFilter::Hard: return "SHADOW_FILTER_HARD";
    case ShadowFilter::Pcf3x3: return "SHADOW_FILTER_PCF3X3";
    case ShadowFilter::Poisson16: return "SHADOW_FILTER_POISSON16";
  }
  return "?";
}

void bindShadowMaps(const ShadowMaps& maps) {
  glBindTextureUnit(kShadowAtlasUnit.index, maps.atlas);
  glBindSampler(kShadowAtlasUnit.index, maps.atlasSampler);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kShadowViewSsbo.index, maps.views);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kLightShadowSsbo.index, maps.lightViews);
}

}  // namespace pbr
