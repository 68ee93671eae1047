#include "ibl/cubemap.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace pbr {

GLuint CubemapTraits::create() { GLuint id = 0; glCreateTextures(GL_TEXTURE_CUBE_MAP, 1, &id); return id; }
void CubemapTraits::destroy(GLuint id) { glDeleteTextures(1, &id); }

size_t bytesPerTexel(GLenum internalFormat) {
  switch (internalFormat) {
    case GL_RGBA32F: return 16;
    case GL_RGBA16F: return 8;
    case GL_RG16F: return 4;
    default: throw std::invalid_argument("bytesPerTexel: unexpected internal format " + std::to_string(internalFormat));
  }
}

Cubemap::Cubemap(const std::string& label, GLenum internalFormat, int faceSize, int levels)
    : handle_(label), format_(internalFormat), faceSize_(faceSize), levels_(levels) {
  glTextureStorage2D(id(), levels, internalFormat, faceSize, faceSize);
  glTextureParameteri(id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTextureParameteri(id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTextureParameteri(id(), GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
}

int Cubemap::faceSize(int level) const { return std::max(faceSize_ >> level, 1); }

size_t Cubemap::bytes() const {
  size_t texels = 0;
  for (int level = 0; level < levels_; ++level) texels += 6 * static_cast<size_t>(faceSize(level)) * faceSize(level);
  return texels * bytesPerTexel(format_);
}

}  // namespace pbr
