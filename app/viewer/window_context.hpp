#pragma once
#include <glm/vec2.hpp>

#include "core/gl/context.hpp"

struct GLFWwindow;

namespace pbr {

// A visible GLFW window with an OpenGL 4.5 core context, behind the same interface as the headless one.
class WindowContext final : public Context {
 public:
  WindowContext(int width, int height, const char* title);
  ~WindowContext() override;

  void makeCurrent() override;
  void swapBuffers() override;

  GLFWwindow* window() const { return window_; }
  bool shouldClose() const;
  glm::ivec2 framebufferSize() const;

 private:
  GLFWwindow* window_ = nullptr;
};

}  // namespace pbr
