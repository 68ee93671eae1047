#include "core/blended_surfaces.hpp"

#include <stdexcept>

namespace pbr {

Transparency parseTransparency(const std::string& name) {
  if (name == "sorted") return Transparency::Sorted;
  if (name == "oit") return Transparency::Oit;
  throw std::invalid_argument("unknown transparency '" + name + "' (expected sorted or oit)");
}

const char* toString(Transparency transparency) {
  return transparency == Transparency::Oit ? "oit" : "sorted";
}

}  // namespace pbr
