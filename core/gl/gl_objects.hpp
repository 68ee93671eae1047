#pragma once
#include <cstddef>
#include <string>
#include <utility>

#include "core/gl/gl.hpp"

namespace pbr {

// Names `id` in debuggers and GL debug messages (glObjectLabel; `identifier` is GL_BUFFER, GL_TEXTURE, ...):
// "gbuffer.normal", "clusters.lightIndices". Cut to the driver's GL_MAX_LABEL_LENGTH, which a longer label would
// exceed with an error.
void labelObject(GLenum identifier, GLuint id, const std::string& label);

// Move-only owner of one GL object name; Traits says how to create and delete it, and its kind of label.
// Every object the project makes is labelled when it is made, so that a capture names all of them.
template <class Traits>
class GlHandle {
 public:
  explicit GlHandle(const std::string& label) : id_(Traits::create()) { labelObject(Traits::kLabelKind, id_, label); }
  GlHandle(GLuint adopt, const std::string& label) : id_(adopt) { labelObject(Traits::kLabelKind, id_, label); }
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
  static constexpr GLenum kLabelKind = GL_BUFFER;
  static GLuint create();
  static void destroy(GLuint id);
};
struct TextureTraits2D {
  static constexpr GLenum kLabelKind = GL_TEXTURE;
  static GLuint create();
  static void destroy(GLuint id);
};
struct FramebufferTraits {
  static constexpr GLenum kLabelKind = GL_FRAMEBUFFER;
  static GLuint create();
  static void destroy(GLuint id);
};
struct VertexArrayTraits {
  static constexpr GLenum kLabelKind = GL_VERTEX_ARRAY;
  static GLuint create();
  static void destroy(GLuint id);
};
struct ProgramTraits {
  static constexpr GLenum kLabelKind = GL_PROGRAM;
  static GLuint create();
  static void destroy(GLuint id);
};
struct SamplerTraits {
  static constexpr GLenum kLabelKind = GL_SAMPLER;
  static GLuint create();
  static void destroy(GLuint id);
};
struct QueryTraits {
  static constexpr GLenum kLabelKind = GL_QUERY;
  static GLuint create();
  static void destroy(GLuint id);
};

// Immutable-storage buffer (glNamedBufferStorage).
class Buffer {
 public:
  Buffer(const std::string& label, size_t bytes, const void* data = nullptr, GLbitfield flags = GL_DYNAMIC_STORAGE_BIT);
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
  Texture(const std::string& label, GLenum internalFormat, int width, int height, int levels = 1);
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
  explicit Framebuffer(const std::string& label) : handle_(label) {}
  GLuint id() const { return handle_.id(); }
  void attach(GLenum attachment, const Texture& texture);
  // Throws std::runtime_error naming the incompleteness status.
  void checkComplete() const;

 private:
  GlHandle<FramebufferTraits> handle_;
};

class VertexArray {
 public:
  explicit VertexArray(const std::string& label) : handle_(label) {}
  GLuint id() const { return handle_.id(); }

 private:
  GlHandle<VertexArrayTraits> handle_;
};

class Program {
 public:
  Program(GLuint adopt, const std::string& label) : handle_(adopt, label) {}
  GLuint id() const { return handle_.id(); }
  void use() const { glUseProgram(handle_.id()); }

 private:
  GlHandle<ProgramTraits> handle_;
};

// Sampling state (wrap modes, filters) kept apart from the images it applies to; bound per texture unit.
class Sampler {
 public:
  Sampler(const std::string& label, GLint wrapS, GLint wrapT, GLint minFilter, GLint magFilter);
  GLuint id() const { return handle_.id(); }

 private:
  GlHandle<SamplerTraits> handle_;
};

// A GL_TIMESTAMP query, made as one (glCreateQueries) so that it exists, and can be labelled, before first use.
class Query {
 public:
  explicit Query(const std::string& label) : handle_(label) {}
  GLuint id() const { return handle_.id(); }

 private:
  GlHandle<QueryTraits> handle_;
};

// Whether a timestamp query's result has arrived (never waits); its time in ns (waits if it has not); the ms from
// one timestamp to a later one (0 where the later reads earlier).
bool queryAvailable(const Query& query);
GLuint64 queryNs(const Query& query);
inline double spanMs(GLuint64 beginNs, GLuint64 endNs) { return endNs > beginNs ? double(endNs - beginNs) * 1e-6 : 0.0; }

// Throws std::runtime_error naming `what` and the GL error if one is pending.
void checkGlError(const std::string& what);

}  // namespace pbr
