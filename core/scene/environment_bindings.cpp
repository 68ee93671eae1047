#include "core/scene/environment_bindings.hpp"

namespace pbr {

ShaderDefines environmentBindingDefines() {
  return bindingDefines({kIblUbo, kIblSpecularUnit, kIblDfgUnit, kIblSheenUnit});
}

}  // namespace pbr
