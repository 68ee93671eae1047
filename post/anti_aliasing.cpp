#include "post/anti_aliasing.hpp"

#include <stdexcept>

namespace pbr {

AntiAliasing parseAntiAliasing(const std::string& name) {
  if (name == "none") return AntiAliasing::None;
  if (name == "fxaa") return AntiAliasing::Fxaa;
  throw std::invalid_argument("unknown anti-aliasing '" + name + "' (expected none or fxaa)");
}

const char* toString(AntiAliasing aa) { return aa == AntiAliasing::Fxaa ? "fxaa" : "none"; }

}  // namespace pbr
