#include "core/gl/shader_library.hpp"

#include <string>
#include <vector>

namespace pbr {

namespace {

GLuint compileStage(GLenum stage, const ExpandedShader& src) {
  GLuint shader = glCreateShader(stage);
  const char* text = src.text.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    GLint len = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &len);
    std::string log(static_cast<size_t>(len > 0 ? len : 1), '\0');
    glGetShaderInfoLog(shader, len, nullptr, log.data());
    glDeleteShader(shader);
    throw ShaderError(remapShaderLog(log.c_str(), src.files));
  }
  return shader;
}

Program link(const std::vector<GLuint>& shaders, const std::string& what, const ShaderDefines& defines) {
  Program program(glCreateProgram(), programLabel(what, defines));
  for (GLuint s : shaders) glAttachShader(program.id(), s);
  glLinkProgram(program.id());
  for (GLuint s : shaders) {
    glDetachShader(program.id(), s);
    glDeleteShader(s);
  }
  GLint ok = GL_FALSE;
  glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
  if (!ok) {
    GLint len = 0;
    glGetProgramiv(program.id(), GL_INFO_LOG_LENGTH, &len);
    std::string log(static_cast<size_t>(len > 0 ? len : 1), '\0');
    glGetProgramInfoLog(program.id(), len, nullptr, log.data());
    throw ShaderError(what + ": link failed: " + log.c_str());
  }
  return program;
}

}  // namespace

Program ShaderLibrary::compute(const std::string& file, const ShaderDefines& defines) const {
  return link({compileStage(GL_COMPUTE_SHADER, expand(file, defines))}, file, defines);
}

Program ShaderLibrary::computeFromSource(const std::string& name, const std::string& text,
                                         const ShaderDefines& defines) const {
  return link({compileStage(GL_COMPUTE_SHADER, expandSource(name, text, defines))}, name, defines);
}

Program ShaderLibrary::graphics(const std::string& vertexFile, const std::string& fragmentFile,
                                const ShaderDefines& defines) const {
  GLuint vs = compileStage(GL_VERTEX_SHADER, expand(vertexFile, defines));
  GLuint fs = 0;
  try {
    fs = compileStage(GL_FRAGMENT_SHADER, expand(fragmentFile, defines));
  } catch (...) {
    glDeleteShader(vs);
    throw;
  }
  return link({vs, fs}, vertexFile + " + " + fragmentFile, defines);
}

}  // namespace pbr
