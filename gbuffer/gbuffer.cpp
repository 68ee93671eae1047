#include "gbuffer/gbuffer.hpp"

#include <stdexcept>

namespace pbr {

GBufferFormats gbufferFormats(GBufferPrecision p) {
  if (p == GBufferPrecision::Lean) return {GL_SRGB8_ALPHA8, GL_RG16, GL_RGBA8, GL_DEPTH_COMPONENT32F};
  return {GL_RGBA32F, GL_RG32F, GL_RGBA32F, GL_DEPTH_COMPONENT32F};
}

// Both layouts hold the same encodings (octahedral normal in [0,1]^2, linear values once fetched), so the shaders
// are the same: only the storage formats differ.
GBuffer::GBuffer(int w, int h, const Texture& radiance, GBufferPrecision p)
    : width(w),
      height(h),
      precision(p),
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
  const GLenum drawBuffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2, GL_COLOR_ATTACHMENT3};
  glNamedFramebufferDrawBuffers(framebuffer.id(), 4, drawBuffers);
  framebuffer.checkComplete();
}

}  // namespace pbr
