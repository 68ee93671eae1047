#include "gbuffer/gbuffer_precision.hpp"

#include <stdexcept>

namespace pbr {

GBufferPrecision parseGBufferPrecision(const std::string& name) {
  if (name == "lean") return GBufferPrecision::Lean;
  if (name == "float") return GBufferPrecision::Float;
  throw std::invalid_argument("unknown G-buffer precision '" + name + "' (expected lean or float)");
}

const char* toString(GBufferPrecision precision) { return precision == GBufferPrecision::Lean ? "lean" : "float"; }

int GBufferLayout::extraBytesPerPixel(GBufferPrecision p) const {
  const int channel = p == GBufferPrecision::Lean ? 8 : 16;
  return (specular ? channel : 0) + (clearcoat ? channel : 0) + (sheen ? (p == GBufferPrecision::Lean ? 4 : 16) : 0);
}

std::string GBufferLayout::describe(GBufferPrecision p) const {
  const int bytes = gbufferBytesPerPixel(p) + extraBytesPerPixel(p);
  std::string name = toString(p), channels = "base colour, normal, material, depth";
  if (specular) name += " + specular", channels += ", dielectric F0 and F90";
  if (clearcoat) name += " + clearcoat", channels += ", clearcoat strength, roughness and normal";
  if (sheen) name += " + sheen", channels += ", sheen colour and roughness";
  return name + ", " + std::to_string(bytes) + " bytes per pixel (" + channels + ")";
}

GBufferLayout materialExtensions(const Scene& scene, bool blended) {
  GBufferLayout used;
  for (const SceneObject& o : scene.objects) {
    const Material& m = o.material;
    if (isForwardShaded(m) != blended) continue;
    used.specular = used.specular || hasDielectricSpecular(m);
    used.clearcoat = used.clearcoat || hasClearcoat(m);
    used.sheen = used.sheen || hasSheen(m);
  }
  return used;
}

GBufferLayout gbufferLayout(const Scene& scene) { return materialExtensions(scene, false); }

}  // namespace pbr
