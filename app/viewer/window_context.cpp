#include "app/viewer/window_context.hpp"

#include <GLFW/glfw3.h>

namespace pbr {

static std::string lastGlfwError() {
  const char* description = nullptr;
  glfwGetError(&description);
  return description ? description : "unknown GLFW error";
}

WindowContext::WindowContext(int width, int height, const char* title) {
  if (!glfwInit()) throw ContextError("GLFW could not initialise: " + lastGlfwError());
  const bool debug = glDebugRequested();
  glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_API);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, debug ? GLFW_TRUE : GLFW_FALSE);
  window_ = glfwCreateWindow(width, height, title, nullptr, nullptr);
  if (!window_) {
    const std::string reason = lastGlfwError();
    glfwTerminate();
    throw ContextError("could not open an OpenGL 4.5 core window: " + reason);
  }
  makeCurrent();
  glfwSwapInterval(0);
  initializeGl("glfw", reinterpret_cast<void* (*)(const char*)>(glfwGetProcAddress), debug);
}

WindowContext::~WindowContext() {
  glfwDestroyWindow(window_);
  glfwTerminate();
}

void WindowContext::makeCurrent() { glfwMakeContextCurrent(window_); }
void WindowContext::swapBuffers() { glfwSwapBuffers(window_); }
bool WindowContext::shouldClose() const { return glfwWindowShouldClose(window_) != 0; }

glm::ivec2 WindowContext::framebufferSize() const {
  glm::ivec2 size;
  glfwGetFramebufferSize(window_, &size.x, &size.y);
  return size;
}

}  // namespace pbr
