#pragma once
#include "core/gl_objects.hpp"

namespace pbr {

// The G-buffer's attachments (layout and bytes per pixel in gbuffer/README.md).
struct GBuffer {
  GBuffer(int width, int height);

  static constexpr int kBytesPerPixel = 4 + 4 + 2 + 4;

  int width, height;
  Texture baseColor;  // GL_SRGB8_ALPHA8
  Texture normal;     // GL_RG16, octahedral
  Texture material;   // GL_RG8, roughness + metalness
  Texture depth;      // GL_DEPTH_COMPONENT32F, reversed Z
  Framebuffer framebuffer;
};

}  // namespace pbr
