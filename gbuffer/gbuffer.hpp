#pragma once
#include <cstddef>
#include <optional>

#include "core/gl/gl_objects.hpp"
#include "gbuffer/gbuffer_precision.hpp"

namespace pbr {

// The internal formats of the attachments for a precision (the frame-size check asks the driver about them).
struct GBufferFormats {
  GLenum baseColor, normal, material, depth;
};
GBufferFormats gbufferFormats(GBufferPrecision precision);

// The internal formats of the specular channel (RGBA16F lean, RGBA32F float) and the clearcoat channel (RGBA16
// lean, RGBA32F float).
GLenum specularFormat(GBufferPrecision precision);
GLenum clearcoatFormat(GBufferPrecision precision);
// The sheen channel's (SRGB8_ALPHA8 lean, RGBA32F float).
GLenum sheenFormat(GBufferPrecision precision);

// The G-buffer's attachments (layout and bytes per pixel in gbuffer/README.md). `radiance` is the frame's HDR
// target, attached as colour attachment 3: the geometry pass writes emitted radiance there and the lighting pass
// adds reflected light on top, so emission needs no attachment of its own. It must outlive the G-buffer.
struct GBuffer {
  GBuffer(int width, int height, const Texture& radiance, GBufferPrecision precision = GBufferPrecision::Lean,
          GBufferLayout layout = {});

  size_t bytes() const {
    return static_cast<size_t>(width) * static_cast<size_t>(height) *
           (gbufferBytesPerPixel(precision) + layout.extraBytesPerPixel(precision));
  }

  int width, height;
  GBufferPrecision precision;
  GBufferLayout layout;
  Texture baseColor;  // GL_SRGB8_ALPHA8 (float: GL_RGBA32F, linear)
  Texture normal;     // GL_RG16, octahedral (float: GL_RG32F)
  Texture material;   // GL_RGBA8, roughness + metalness + occlusion (float: GL_RGBA32F)
  Texture depth;      // GL_DEPTH_COMPONENT32F, reversed Z
  // GL_RGBA16F dielectric F0 / 0.04 and F90 (float: GL_RGBA32F), colour attachment 4: with layout.specular only.
  std::optional<Texture> specular;
  // GL_RGBA16 clearcoat strength, roughness and octahedral normal (float: GL_RGBA32F), colour attachment 5: with
  // layout.clearcoat only.
  std::optional<Texture> clearcoat;
  // GL_SRGB8_ALPHA8 sheen colour and roughness (float: GL_RGBA32F), colour attachment 6: with layout.sheen only.
  std::optional<Texture> sheen;
  Framebuffer framebuffer;
};

}  // namespace pbr
