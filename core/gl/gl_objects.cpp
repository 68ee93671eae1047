#include "core/gl/gl_objects.hpp"

#include <cstdio>
#include <stdexcept>

namespace pbr {

GLuint BufferTraits::create() { GLuint id = 0; glCreateBuffers(1, &id); return id; }
void BufferTraits::destroy(GLuint id) { glDeleteBuffers(1, &id); }
GLuint TextureTraits2D::create() { GLuint id = 0; glCreateTextures(GL_TEXTURE_2D, 1, &id); return id; }
void TextureTraits2D::destroy(GLuint id) { glDeleteTextures(1, &id); }
GLuint FramebufferTraits::create() { GLuint id = 0; glCreateFramebuffers(1, &id); return id; }
void FramebufferTraits::destroy(GLuint id) { glDeleteFramebuffers(1, &id); }
GLuint VertexArrayTraits::create() { GLuint id = 0; glCreateVertexArrays(1, &id); return id; }
void VertexArrayTraits::destroy(GLuint id) { glDeleteVertexArrays(1, &id); }
GLuint ProgramTraits::create() { return glCreateProgram(); }
void ProgramTraits::destroy(GLuint id) { glDeleteProgram(id); }
GLuint SamplerTraits::create() { GLuint id = 0; glCreateSamplers(1, &id); return id; }
void SamplerTraits::destroy(GLuint id) { glDeleteSamplers(1, &id); }
GLuint QueryTraits::create() { GLuint id = 0; glCreateQueries(GL_TIMESTAMP, 1, &id); return id; }
void QueryTraits::destroy(GLuint id) { glDeleteQueries(1, &id); }

void labelObject(GLenum identifier, GLuint id, const std::string& label) {
  GLint maxLength = 0;
  glGetIntegerv(GL_MAX_LABEL_LENGTH, &maxLength);
  const size_t fits = maxLength > 0 ? static_cast<size_t>(maxLength) - 1 : 0;
  glObjectLabel(identifier, id, -1, label.substr(0, fits).c_str());
}

Buffer::Buffer(const std::string& label, size_t bytes, const void* data, GLbitfield flags)
    : handle_(label), size_(bytes) {
  // Zero-sized storage is invalid in GL; one word keeps binding an empty list legal.
  glNamedBufferStorage(id(), static_cast<GLsizeiptr>(bytes ? bytes : 4), bytes ? data : nullptr, flags);
}

void Buffer::upload(const void* data, size_t bytes, size_t offset) {
  if (offset + bytes > size_) throw std::out_of_range("buffer upload past the end of its storage");
  if (bytes) glNamedBufferSubData(id(), static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(bytes), data);
}

void Buffer::bindBase(GLenum target, GLuint index) const { glBindBufferBase(target, index, id()); }

void Buffer::bindRange(GLenum target, GLuint index, size_t offset, size_t bytes) const {
  glBindBufferRange(target, index, id(), static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(bytes));
}

Texture::Texture(const std::string& label, GLenum internalFormat, int width, int height, int levels)
    : handle_(label), format_(internalFormat), width_(width), height_(height) {
  glTextureStorage2D(id(), levels, internalFormat, width, height);
  glTextureParameteri(id(), GL_TEXTURE_MIN_FILTER, levels > 1 ? GL_LINEAR_MIPMAP_LINEAR : GL_NEAREST);
  glTextureParameteri(id(), GL_TEXTURE_MAG_FILTER, levels > 1 ? GL_LINEAR : GL_NEAREST);
  glTextureParameteri(id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

Sampler::Sampler(const std::string& label, GLint wrapS, GLint wrapT, GLint minFilter, GLint magFilter)
    : handle_(label) {
  glSamplerParameteri(id(), GL_TEXTURE_WRAP_S, wrapS);
  glSamplerParameteri(id(), GL_TEXTURE_WRAP_T, wrapT);
  glSamplerParameteri(id(), GL_TEXTURE_MIN_FILTER, minFilter);
  glSamplerParameteri(id(), GL_TEXTURE_MAG_FILTER, magFilter);
}

void Framebuffer::attach(GLenum attachment, const Texture& texture) {
  glNamedFramebufferTexture(id(), attachment, texture.id(), 0);
}

void Framebuffer::checkComplete() const {
  const GLenum status = glCheckNamedFramebufferStatus(id(), GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    throw std::runtime_error("framebuffer incomplete (status 0x" + std::to_string(status) + ")");
  }
}

void checkGlError(const std::string& what) {
  const GLenum err = glGetError();
  if (err != GL_NO_ERROR) {
    char code[16];
    std::snprintf(code, sizeof code, "0x%04X", err);
    throw std::runtime_error("OpenGL error " + std::string(code) + " after " + what);
  }
}

bool queryAvailable(const Query& query) {
  GLint available = 0;
  glGetQueryObjectiv(query.id(), GL_QUERY_RESULT_AVAILABLE, &available);
  return available != 0;
}

GLuint64 queryNs(const Query& query) {
  GLuint64 ns = 0;
  glGetQueryObjectui64v(query.id(), GL_QUERY_RESULT, &ns);
  return ns;
}

}  // namespace pbr
