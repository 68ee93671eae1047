#include "app/accuracy/pair_cost_settings.hpp"

#include <stdexcept>

namespace pbr {

FixtureMaterial parseFixtureMaterial(const std::string& name) {
  for (const FixtureMaterial m :
       {FixtureMaterial::Core, FixtureMaterial::Specular, FixtureMaterial::Clearcoat, FixtureMaterial::Sheen}) {
    if (name == toString(m)) return m;
  }
  throw std::invalid_argument("unknown fixture material '" + name + "' (expected core, specular, clearcoat or sheen)");
}

const char* toString(FixtureMaterial material) {
  switch (material) {
    case FixtureMaterial::Core: return "core";
    case FixtureMaterial::Specular: return "specular";
    case FixtureMaterial::Clearcoat: return "clearcoat";
    case FixtureMaterial::Sheen: return "sheen";
  }
  return "?";
}

}  // namespace pbr
