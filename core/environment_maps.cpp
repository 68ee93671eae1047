#include "core/environment_maps.hpp"

#include "core/bindings.hpp"

namespace pbr {

void bindEnvironmentMaps(const EnvironmentMaps& maps) {
  glBindBufferBase(GL_UNIFORM_BUFFER, binding::kIblUbo, maps.irradianceBlock);
  glBindTextureUnit(binding::kIblSpecularUnit, maps.specularCube);
  glBindSampler(binding::kIblSpecularUnit, maps.specularSampler);
  glBindTextureUnit(binding::kIblDfgUnit, maps.dfgTable);
  glBindSampler(binding::kIblDfgUnit, maps.dfgSampler);
  glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
}

}  // namespace pbr
