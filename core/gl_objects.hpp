#pragma once
#include <cstddef>
#include <string>
#include <utility>

#include "core/gl.hpp"

namespace pbr {

// Move-only owner of one GL object name; Traits says how to create and delete it.
template <class Traits>
class GlHandle {
 public:
  GlHandle() : id_(Traits::create()) {}
  explicit GlHandle(GLuint adopt) : id_(adopt) {}
  ~GlHandle() { reset(); }
  GlHandle(const GlHandle&) = delete;
  GlHandle& operator=(const GlHandle&) = delete;
  GlHandle(GlHandle&& other) noexcept : id_(std::exchange(other.id_, 0)) {}
  GlHandle& operator=(GlHandle&& other) noexcept {
    if (this != &other) {
      reset();
      id_ = std::exchange(other.id_, 0);
    }
    return *this;
  }
  GLuint id() const { return id_; }

 private:
  void reset() {
    if (id_) Traits::destroy(id_);
    id_ = 0;
  }
  GLuint id_;
};

struct BufferTraits {
  static GLuint create();
  static void destroy(GLuint id);
};
struct TextureTraits2D {
  static GLuint create();
  static void destroy(GLuint id);
};
struct FramebufferTraits {
  static GLuint create();
  static void destroy(GLuint id);
};
struct VertexArrayTraits {
  static GLuint create();
  static void destroy(GLuint id);
};
struct ProgramTraits {
  static GLuint create();
  static void destroy(GLuint id);
};
struct SamplerTraits {
  static GLuint create();
  static void destroy(GLuint id);
};
struct QueryTraits {
  static GLuint create();
  static void destroy(GLuint id);
};

// Immutable-storage buffer (glNamedBufferStorage).
class Buffer {
 public:
  Buffer(size_t bytes, const void* data = nullptr, GLbitfield flags = GL_DYNAMIC_STORAGE_BIT);
  GLuint id() const { return handle_.id(); }
  size_t size() const { return size_; }
  void upload(const void* data, size_t bytes, size_t offset = 0);
  void bindBase(GLenum target, GLuint index) const;
  void bindRange(GLenum target, GLuint index, size_t offset, size_t bytes) const;

 private:
  GlHandle<BufferTraits> handle_;
  size_t size_;
};

// Immutable-storage 2D texture with nearest filtering (G-buffer and image targets are fetched per texel).
class Texture {
 public:
  Texture(GLenum internalFormat, int width, int height, int levels = 1);
  GLuint id() const { return handle_.id(); }
  GLenum format() const { return format_; }
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  GlHandle<TextureTraits2D> handle_;
  GLenum format_;
  int width_, height_;
};

class Framebuffer {
 public:
  GLuint id() const { return handle_.id(); }
  void attach(GLenum attachment, const Texture& texture);
  // Throws std::runtime_error naming the incompleteness status.
  void checkComplete() const;

 private:
  GlHandle<FramebufferTraits> handle_;
};

class VertexArray {
 public:
  GLuint id() const { return handle_.id(); }

 private:
  GlHandle<VertexArrayTraits> handle_;
};

class Program {
 public:
  explicit Program(GLuint adopt) : handle_(adopt) {}
  GLuint id() const { return handle_.id(); }
  void use() const { glUseProgram(handle_.id()); }

 private:
  GlHandle<ProgramTraits> handle_;
};

// Sampling state (wrap modes, filters) kept apart from the images it applies to; bound per texture unit.
class Sampler {
 public:
  Sampler(GLint wrapS, GLint wrapT, GLint minFilter, GLint magFilter);
  GLuint id() const { return handle_.id(); }

 private:
  GlHandle<SamplerTraits> handle_;
};

class Query {
 public:
  GLuint id() const { return handle_.id(); }

 private:
  GlHandle<QueryTraits> handle_;
};

// Throws std::runtime_error naming `what` and the GL error if one is pending.
void checkGlError(const std::string& what);

}  // namespace pbr
