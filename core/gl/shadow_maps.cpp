#include "core/gl/shadow_maps.hpp"

namespace pbr {

void bindShadowMaps(const ShadowMaps& maps) {
  glBindTextureUnit(kShadowAtlasUnit.index, maps.atlas);
  glBindSampler(kShadowAtlasUnit.index, maps.atlasSampler);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kShadowViewSsbo.index, maps.views);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kLightShadowSsbo.index, maps.lightViews);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kShadowSquareSsbo.index, maps.squares);
}

}  // namespace pbr
