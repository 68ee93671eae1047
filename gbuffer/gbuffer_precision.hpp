#pragma once
#include <string>

#include "core/scene/scene.hpp"

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

// The channels a scene's materials need beyond the core metal-rough ones (gbuffer/README.md): chosen when the scene
// loads, so that a scene whose materials use no extension keeps the 16-byte layout and its programs. Each is set
// where a material sets its extension to other than the core material's values.
struct GBufferLayout {
  bool specular = false;   // KHR_materials_ior / _specular: the dielectric's F0 and F90 (hasDielectricSpecular)
  bool clearcoat = false;  // KHR_materials_clearcoat: its strength, roughness and normal (a strength above 0)
  bool sheen = false;      // KHR_materials_sheen: its colour and roughness (a colour other than black)
  int extraBytesPerPixel(GBufferPrecision precision) const;
  // "base colour, normal, material, depth" and the extra channels, with bytes per pixel: "lean, 16 bytes per pixel
  // (base colour, normal, material, depth)", "lean + specular, 24 bytes per pixel (...)".
  std::string describe(GBufferPrecision precision) const;
  bool operator==(const GBufferLayout& o) const {
    return specular == o.specular && clearcoat == o.clearcoat && sheen == o.sheen;
  }
};
// The extensions the scene's forward-shaded materials (`blended`: BLEND or transmissive, isForwardShaded), or its
// other materials, use: for the others, the G-buffer's layout; for the forward-shaded ones, the permutation the
// transparency pass shades them with.
GBufferLayout materialExtensions(const Scene& scene, bool blended);
GBufferLayout gbufferLayout(const Scene& scene);  // materialExtensions(scene, false)

}  // namespace pbr
