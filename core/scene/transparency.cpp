#include "core/scene/transparency.hpp"

#include <stdexcept>

namespace pbr {

Transparency parseTransparency(const std::string& name) {
  if (name == "sorted") return Transparency::Sorted;
  if (name == "oit") return Transparency::Oit;
  if (name == "exact") return Transparency::Exact;
  throw std::invalid_argument("unknown transparency '" + name + "' (expected sorted, oit or exact)");
}

const char* toString(Transparency transparency) {
  switch (transparency) {
    case Transparency::Sorted: return "sorted";
    case Transparency::Oit: return "oit";
    case Transparency::Exact: return "exact";
  }
  return "?";
}

}  // namespace pbr
