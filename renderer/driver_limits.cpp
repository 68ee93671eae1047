#include "renderer/driver_limits.hpp"

#include <stdexcept>

#include "core/gl/hdr_format.hpp"
#include "gbuffer/gbuffer.hpp"
#include "renderer/renderer_config.hpp"

namespace pbr {

namespace {

const char* formatName(GLenum format) {
  switch (format) {
    case GL_SRGB8_ALPHA8: return "SRGB8_ALPHA8";
    case GL_RGBA8: return "RGBA8";
    case GL_RG16: return "RG16";
    case GL_RG32F: return "RG32F";
    case GL_RGBA16F: return "RGBA16F";
    case GL_R11F_G11F_B10F: return "R11F_G11F_B10F";
    case GL_RGBA32F: return "RGBA32F";
    case GL_DEPTH_COMPONENT32F: return "DEPTH_COMPONENT32F";
  }
  return "colour";
}

}  // namespace

std::vector<GLenum> frameFormats(const RendererConfig& config, const GBufferLayout& layout) {
  const GBufferFormats g = gbufferFormats(config.gbuffer);
  std::vector<GLenum> formats = {g.baseColor, g.normal, g.material, g.depth, glInternalFormat(config.hdrFormat),
                                 GL_RGBA8};
  if (layout.specular) formats.push_back(specularFormat(config.gbuffer));
  if (layout.clearcoat) formats.push_back(clearcoatFormat(config.gbuffer));
  if (layout.sheen) formats.push_back(sheenFormat(config.gbuffer));
  return formats;
}

FrameLimits queryFrameLimits() {
  FrameLimits limits;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &limits.maxTextureSize);
  limits.availableBytes = availableMemoryBytes();
  return limits;
}

void checkFrameFormats(int width, int height, const std::string& option, const std::vector<GLenum>& formats) {
  for (const GLenum format : formats) {
    // A proxy takes no storage: the driver fills in the level's width, or 0 if it could not create the texture.
    const bool depth = format == GL_DEPTH_COMPONENT32F;
    glTexImage2D(GL_PROXY_TEXTURE_2D, 0, static_cast<GLint>(format), width, height, 0,
                 depth ? GL_DEPTH_COMPONENT : GL_RGBA, GL_FLOAT, nullptr);
    GLint created = 0;
    glGetTexLevelParameteriv(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &created);
    if (created == 0) {
      throw std::runtime_error(option + " " + std::to_string(width) + "x" + std::to_string(height) +
                               ": the OpenGL driver refuses " + formatName(format) +
                               " textures of that size (proxy texture test); try a smaller size");
    }
  }
}

}  // namespace pbr
