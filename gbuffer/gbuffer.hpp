#pragma once
#include <cstddef>

#include "core/gl_objects.hpp"

namespace pbr {

// The G-buffer's attachments (layout and bytes per pixel in gbuffer/README.md). `radiance` is the frame's HDR
// target, attached as colour attachment 3: the geometry pass writes emitted radiance there and the lighting pass
// adds reflected light on top, so emission needs no attachment of its own. It must outlive the G-buffer.
struct GBuffer {
  GBuffer(int width, int height, const Texture& radiance);

  static constexpr int kBytesPerPixel = 4 + 4 + 4 + 4;
  size_t bytes() const { return static_cast<size_t>(width) * static_cast<size_t>(height) * kBytesPerPixel; }

  int width, height;
  Texture baseColor;  // GL_SRGB8_ALPHA8
  Texture normal;     // GL_RG16, octahedral
  Texture material;   // GL_RGBA8, roughness + metalness + occlusion
  Texture depth;      // GL_DEPTH_COMPONENT32F, reversed Z
  Framebuffer framebuffer;
};

}  // namespace pbr
