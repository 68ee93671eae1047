#include "core/gl/context.hpp"

#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "core/gl/gl.hpp"

namespace pbr {

bool glHasExtension(const char* name) {
  GLint count = 0;
  glGetIntegerv(GL_NUM_EXTENSIONS, &count);
  for (GLint i = 0; i < count; ++i) {
    const auto* extension = reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, GLuint(i)));
    if (extension && std::strcmp(extension, name) == 0) return true;
  }
  return false;
}

bool glDebugRequested() {
  const char* env = std::getenv("PBR_GL_DEBUG");
  if (env) return std::strcmp(env, "0") != 0;
#ifdef NDEBUG
  return false;
#else
  return true;
#endif
}

static void GLAD_API_PTR forwardDebugMessage(GLenum, GLenum type, GLuint, GLenum severity, GLsizei,
                                         const GLchar* message, const void*) {
  if (severity == GL_DEBUG_SEVERITY_NOTIFICATION) return;
  const char* kind = type == GL_DEBUG_TYPE_ERROR ? "error" : type == GL_DEBUG_TYPE_PERFORMANCE ? "performance" : "message";
  std::fprintf(stderr, "gl %s: %s\n", kind, message);
}

void Context::initializeGl(const std::string& platform, void* (*getProc)(const char*), bool debug) {
  int version = gladLoadGL(reinterpret_cast<GLADloadfunc>(getProc));
  if (version == 0) throw ContextError("could not load OpenGL entry points");
  if (GLAD_VERSION_MAJOR(version) < 4 || (GLAD_VERSION_MAJOR(version) == 4 && GLAD_VERSION_MINOR(version) < 5)) {
    throw ContextError("OpenGL 4.5 core is required, the context offers " + std::to_string(GLAD_VERSION_MAJOR(version)) +
                       "." + std::to_string(GLAD_VERSION_MINOR(version)));
  }
  auto str = [](GLenum name) {
    const GLubyte* s = glGetString(name);
    return s ? std::string(reinterpret_cast<const char*>(s)) : std::string();
  };
  info_ = {platform, str(GL_RENDERER), str(GL_VERSION), str(GL_VENDOR)};
  if (debug) {
    glEnable(GL_DEBUG_OUTPUT);
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDebugMessageCallback(forwardDebugMessage, nullptr);
  }
}

}  // namespace pbr
