#pragma once
#include <string>

namespace pbr {

// Lean: the 16-byte layout of gbuffer/README.md. Float: the same channels unquantised (RGBA32F base colour and
// material, RG32F octahedral normal; 44 bytes per pixel), to measure what the lean layout's quantisation costs.
enum class GBufferPrecision { Lean, Float };
GBufferPrecision parseGBufferPrecision(const std::string& name);  // "lean" | "float"
const char* toString(GBufferPrecision precision);

// Bytes per pixel of the attachments (gbuffer/README.md): lean 4 + 4 + 4 + 4, float 16 + 8 + 16 + 4.
constexpr int gbufferBytesPerPixel(GBufferPrecision precision) {
  return precision == GBufferPrecision::Lean ? 4 + 4 + 4 + 4 : 16 + 8 + 16 + 4;
}

}  // namespace pbr
