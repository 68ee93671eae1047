#include "gbuffer/gbuffer.hpp"

#include <stdexcept>

namespace pbr {

GBufferPrecision parseGBufferPrecision(const std::string& name) {
  if (name == "lean") return GBufferPrecision::Lean;
  if (name == "float") return GBufferPrecision::Float;
  throw std::invalid_argument("unknown G-buffer precision '" + name + "' (expected lean or float)");
}

const char* toString(GBufferPrecision precision) { return precision == GBufferPrecision::Lean ? "lean" : "float"; }

GBufferFormats gbufferFormats(GBufferPrecision p) {
  if (p == GBufferPrecision::Lean) return {GL_SRGB8_ALPHA8, GL_RG16, GL_RGBA8, GL_DEPTH_COMPONENT32F};
  return {GL_RGBA32F, GL_RG32F, GL_RGBA32F, GL_DEPTH_COMPONENT32F};
}

int GBufferLayout::extraBytesPerPixel(GBufferPrecision p) const {
  return specular ? (p == GBufferPrecision::Lean ? 8 : 16) : 0;
}

std::string GBufferLayout::describe(GBufferPrecision p) const {
  const int bytes = (p == GBufferPrecision::Lean ? GBuffer::kBytesPerPixel : GBuffer::kFloatBytesPerPixel) +
                    extraBytesPerPixel(p);
  return std::string(toString(p)) + (specular ? " + specular" : "") + ", " + std::to_string(bytes) +
         " bytes per pixel (base colour, normal, material, depth" + (specular ? ", dielectric F0 and F90" : "") +
         ")";
}

GBufferLayout gbufferLayout(const Scene& scene) { return {hasSpecularMaterial(scene, false)}; }

GLenum specularFormat(GBufferPrecision p) { return p == GBufferPrecision::Lean ? GL_RGBA16F : GL_RGBA32F; }

// Both layouts hold the same encodings (octahedral normal in [0,1]^2, linear values once fetched), so the shaders
// are the same: only the storage formats differ.
GBuffer::GBuffer(int w, int h, const Texture& radiance, GBufferPrecision p, GBufferLayout l)
    : width(w),
      height(h),
      precision(p),
      layout(l),
      baseColor("gbuffer.baseColor", gbufferFormats(p).baseColor, w, h),
      normal("gbuffer.normal", gbufferFormats(p).normal, w, h),
      material("gbuffer.material", gbufferFormats(p).material, w, h),
      depth("gbuffer.depth", gbufferFormats(p).depth, w, h),
      framebuffer("gbuffer") {
  const GLenum f = radiance.format();
  if (radiance.width() != w || radiance.height() != h ||
      (f != GL_RGBA16F && f != GL_R11F_G11F_B10F && f != GL_RGBA32F)) {
    throw std::invalid_argument("G-buffer: the radiance target must be RGBA16F, R11F_G11F_B10F or RGBA32F of the "
                                "G-buffer's size");
  }
  framebuffer.attach(GL_COLOR_ATTACHMENT0, baseColor);
  framebuffer.attach(GL_COLOR_ATTACHMENT1, normal);
  framebuffer.attach(GL_COLOR_ATTACHMENT2, material);
  framebuffer.attach(GL_COLOR_ATTACHMENT3, radiance);
  framebuffer.attach(GL_DEPTH_ATTACHMENT, depth);
  if (layout.specular) {
    specular.emplace("gbuffer.specular", specularFormat(p), w, h);
    framebuffer.attach(GL_COLOR_ATTACHMENT4, *specular);
  }
  const GLenum drawBuffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2, GL_COLOR_ATTACHMENT3,
                                GL_COLOR_ATTACHMENT4};
  glNamedFramebufferDrawBuffers(framebuffer.id(), layout.specular ? 5 : 4, drawBuffers);
  framebuffer.checkComplete();
}

}  // namespace pbr
