#include "gbuffer/gbuffer_precision.hpp"

#include <stdexcept>

namespace pbr {

GBufferPrecision parseGBufferPrecision(const std::string& name) {
  if (name == "lean") return GBufferPrecision::Lean;
  if (name == "float") return GBufferPrecision::Float;
  throw std::invalid_argument("unknown G-buffer precision '" + name + "' (expected lean or float)");
}

const char* toString(GBufferPrecision precision) { return precision == GBufferPrecision::Lean ? "lean" : "float"; }

}  // namespace pbr
