#pragma once
#include <cstddef>

#include "core/gl/gl_objects.hpp"
#include "gbuffer/gbuffer_precision.hpp"

namespace pbr {

// The internal formats of the attachments for a precision (the frame-size check asks the driver about them).
struct GBufferFormats {
  GLenum baseColor, normal, material, depth;
};
GBufferFormats gbufferFormats(GBufferPrecision precision);

// The G-buffer's attachments (layout and bytes per pixel in gbuffer/README.md). `radiance` is the frame's HDR
// target, attached as colour attachment 3: the geometry pass writes emitted radiance there and the lighting pass
// adds reflected light on top, so emission needs no attachment of its own. It must outlive the G-buffer.
struct GBuffer {
  GBuffer(int width, int height, const Texture& radiance, GBufferPrecision precision = GBufferPrecision::Lean);

  size_t bytes() const {
    return static_cast<size_t>(width) * static_cast<size_t>(height) * gbufferBytesPerPixel(precision);
  }

  int width, height;
  GBufferPrecision precision;
  Texture baseColor;  // GL_SRGB8_ALPHA8 (float: GL_RGBA32F, linear)
  Texture normal;     // GL_RG16, octahedral (float: GL_RG32F)
  Texture material;   // GL_RGBA8, roughness + metalness + occlusion (float: GL_RGBA32F)
  Texture depth;      // GL_DEPTH_COMPONENT32F, reversed Z
  Framebuffer framebuffer;
};

}  // namespace pbr
