#pragma once
#include <string>
#include <vector>

struct GLFWwindow;
struct ImGuiContext;

namespace pbr {

class Viewer;

// The viewer's Dear ImGui overlay: per-pass frame times, light statistics, the controls (through the viewer's
// handlers, as the keys), the environment picker, the camera with "save as scene JSON", and the keys. It owns the
// ImGui context and its GLFW and OpenGL 3 backends; made after the viewer's input callbacks, which the GLFW
// backend chains behind its own, and gone before the window and its GL context.
class Overlay {
 public:
  explicit Overlay(GLFWwindow* window);
  ~Overlay();
  Overlay(const Overlay&) = delete;
  Overlay& operator=(const Overlay&) = delete;

  // Whether the last frame's widgets take the mouse or the keyboard, which the view then leaves alone.
  bool wantsMouse() const;
  bool wantsKeyboard() const;

  // Builds this frame's widgets, applies what they changed through the viewer's handlers, and draws them into the
  // window's default framebuffer.
  void draw(Viewer& viewer);

 private:
  void frameTimes(const Viewer& viewer);
  void lightStatistics(Viewer& viewer);
  void controls(Viewer& viewer);
  void shadowControls(Viewer& viewer);  // which lights cast, the filter and the atlas size
  void environment(Viewer& viewer);
  void camera(Viewer& viewer);
  void animation(Viewer& viewer);  // the glTF animation the scene plays: its time, a slider, pause
  void keys();

  ImGuiContext* context_ = nullptr;
  int lightCountInput_ = -1;  // the count field's value while it is edited; -1: show the viewer's
  std::string environmentFolder_;
  std::vector<std::string> environmentFiles_;
  bool environmentsListed_ = false;
  std::string environmentMessage_;
  char scenePath_[512] = "pbr-view-scene.json";
  std::string sceneMessage_;
};

}  // namespace pbr
