#include "core/gl/hdr_format.hpp"

namespace pbr {

GLenum glInternalFormat(HdrFormat format) {
  switch (format) {
    case HdrFormat::Rgba16f: return GL_RGBA16F;
    case HdrFormat::R11g11b10f: return GL_R11F_G11F_B10F;
    case HdrFormat::Rgba32f: return GL_RGBA32F;
  }
  return GL_RGBA16F;
}

HdrFormat hdrFormatOf(GLenum internalFormat) {
  switch (internalFormat) {
    case GL_R11F_G11F_B10F: return HdrFormat::R11g11b10f;
    case GL_RGBA32F: return HdrFormat::Rgba32f;
    default: return HdrFormat::Rgba16f;
  }
}

}  // namespace pbr
