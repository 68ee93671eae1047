#pragma once
#include <cstddef>
#include <string>

#include "core/gl/gl_objects.hpp"

namespace pbr {

struct CubemapTraits {
  static constexpr GLenum kLabelKind = GL_TEXTURE;
  static GLuint create();
  static void destroy(GLuint id);
};

// Bytes per texel of the formats the IBL maps use (RGBA32F, RGBA16F, RG16F); throws std::invalid_argument for
// any other.
size_t bytesPerTexel(GLenum internalFormat);

// Immutable-storage cube map, faces in the GL order +X, -X, +Y, -Y, +Z, -Z, filtered trilinearly and clamped at
// the face edges (GL_TEXTURE_CUBE_MAP_SEAMLESS, global state, filters across them).
class Cubemap {
 public:
  Cubemap(const std::string& label, GLenum internalFormat, int faceSize, int levels);
  GLuint id() const { return handle_.id(); }
  GLenum format() const { return format_; }
  int levels() const { return levels_; }
  int faceSize(int level = 0) const;
  size_t bytes() const;

 private:
  GlHandle<CubemapTraits> handle_;
  GLenum format_;
  int faceSize_, levels_;
};

}  // namespace pbr
