#include "gbuffer/gbuffer.hpp"

namespace pbr {

GBuffer::GBuffer(int w, int h)
    : width(w),
      height(h),
      baseColor(GL_SRGB8_ALPHA8, w, h),
      normal(GL_RG16, w, h),
      material(GL_RG8, w, h),
      depth(GL_DEPTH_COMPONENT32F, w, h) {
  framebuffer.attach(GL_COLOR_ATTACHMENT0, baseColor);
  framebuffer.attach(GL_COLOR_ATTACHMENT1, normal);
  framebuffer.attach(GL_COLOR_ATTACHMENT2, material);
  framebuffer.attach(GL_DEPTH_ATTACHMENT, depth);
  const GLenum drawBuffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2};
  glNamedFramebufferDrawBuffers(framebuffer.id(), 3, drawBuffers);
  framebuffer.checkComplete();
}

}  // namespace pbr
