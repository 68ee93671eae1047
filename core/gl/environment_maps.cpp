#include "core/gl/environment_maps.hpp"

namespace pbr {

void bindEnvironmentMaps(const EnvironmentMaps& maps) {
  glBindBufferBase(GL_UNIFORM_BUFFER, kIblUbo.index, maps.irradianceBlock);
  glBindTextureUnit(kIblSpecularUnit.index, maps.specularCube);
  glBindSampler(kIblSpecularUnit.index, maps.specularSampler);
  glBindTextureUnit(kIblDfgUnit.index, maps.dfgTable);
  glBindSampler(kIblDfgUnit.index, maps.dfgSampler);
  if (maps.sheenCube) {
    glBindTextureUnit(kIblSheenUnit.index, maps.sheenCube);
    glBindSampler(kIblSheenUnit.index, maps.specularSampler);
  }
  glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
}

}  // namespace pbr
