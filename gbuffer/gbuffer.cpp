#include "gbuffer/gbuffer.hpp"

#include <stdexcept>
#include <vector>

namespace pbr {

GBufferFormats gbufferFormats(GBufferPrecision p) {
  if (p == GBufferPrecision::Lean) return {GL_SRGB8_ALPHA8, GL_RG16, GL_RGBA8, GL_DEPTH_COMPONENT32F};
  return {GL_RGBA32F, GL_RG32F, GL_RGBA32F, GL_DEPTH_COMPONENT32F};
}

GLenum specularFormat(GBufferPrecision p) { return p == GBufferPrecision::Lean ? GL_RGBA16F : GL_RGBA32F; }
GLenum clearcoatFormat(GBufferPrecision p) { return p == GBufferPrecision::Lean ? GL_RGBA16 : GL_RGBA32F; }
GLenum sheenFormat(GBufferPrecision p) { return p == GBufferPrecision::Lean ? GL_SRGB8_ALPHA8 : GL_RGBA32F; }

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
  // Each extension's channel keeps its attachment whether or not the other's exists (the G-buffer programs write
  // fixed locations): a missing one is GL_NONE.
  std::vector<GLenum> drawBuffers = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2,
                                     GL_COLOR_ATTACHMENT3};
  const bool anyAfterSpecular = layout.clearcoat || layout.sheen;
  if (layout.specular || anyAfterSpecular) drawBuffers.push_back(layout.specular ? GL_COLOR_ATTACHMENT4 : GL_NONE);
  if (anyAfterSpecular) drawBuffers.push_back(layout.clearcoat ? GL_COLOR_ATTACHMENT5 : GL_NONE);
  if (layout.sheen) drawBuffers.push_back(GL_COLOR_ATTACHMENT6);
  if (layout.specular) {
    specular.emplace("gbuffer.specular", specularFormat(p), w, h);
    framebuffer.attach(GL_COLOR_ATTACHMENT4, *specular);
  }
  if (layout.clearcoat) {
    clearcoat.emplace("gbuffer.clearcoat", clearcoatFormat(p), w, h);
    framebuffer.attach(GL_COLOR_ATTACHMENT5, *clearcoat);
  }
  if (layout.sheen) {
    sheen.emplace("gbuffer.sheen", sheenFormat(p), w, h);
    framebuffer.attach(GL_COLOR_ATTACHMENT6, *sheen);
  }
  glNamedFramebufferDrawBuffers(framebuffer.id(), GLsizei(drawBuffers.size()), drawBuffers.data());
  framebuffer.checkComplete();
}

}  // namespace pbr
