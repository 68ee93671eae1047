#include "gbuffer/gbuffer.hpp"

#include <stdexcept>

namespace pbr {

GBuffer::GBuffer(int w, int h, const Texture& radiance)
    : width(w),
      height(h),
      baseColor(GL_SRGB8_ALPHA8, w, h),
      normal(GL_RG16, w, h),
      material(GL_RGBA8, w, h),
      depth(GL_DEPTH_COMPONENT32F, w, h) {
  if (radiance.width() != w || radiance.height() != h || radiance.format() != GL_RGBA16F) {
    throw std::invalid_argument("G-buffer: the radiance target must be RGBA16F of the G-buffer's size");
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
