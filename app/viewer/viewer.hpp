#pragma once
#include <chrono>
#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "app/viewer/orbit_camera.hpp"
#include "renderer/renderer.hpp"
#include "core/builtin_scenes.hpp"
#include "core/window_context.hpp"

namespace pbr {

// What the window shows: the final frame (no channel) or one of kDebugChannels, as `pbr render --debug`.
const char* viewName(const std::optional<DebugChannel>& view);  // "final" or the channel's name

struct ViewerOptions {
  std::string sceneName = "default";  // built-in name or scene file, re-resolved when the light count changes
  SceneParams sceneParams;
  glm::ivec2 size{1280, 720};  // window size
  FrameOptions frame;          // model, culling, exposure at start
  bool paused = false;         // light animation
  std::string screenshot;      // F12 and the end of a --frames run write here; empty: F12 numbers its files
  std::string timing = "auto";
};

// An interactive window over the same Renderer as the headless path: an orbit camera, runtime switches of the
// shading model, culling and debug view, animated lights, and the frame and pass times in the title.
class Viewer {
 public:
  Viewer(const ViewerOptions& options, Scene scene);
  Viewer(const Viewer&) = delete;
  Viewer& operator=(const Viewer&) = delete;

  // Renders until the window closes, or `frames` frames when > 0 and then writes the screenshot if one was named.
  void run(int frames);
  // One frame: pending resize, held fly keys, light animation, render, present, title, events.
  void frame();
  // The action of one key press (a GLFW key code), as the window's key callback calls it; other keys do nothing.
  void handleKey(int key);
  // Rebuilds what the frame size owns (G-buffer, HDR and LDR targets, cluster grid) at `width` x `height`; the
  // scene's uploads, IBL maps and compiled programs stay.
  void resize(int width, int height);

  ImageRgba8 screenshot() const;  // what the window shows, rows top-down
  void saveScreenshot(const std::string& path) const;

  const FrameOptions& frameOptions() const { return options_.frame; }
  std::optional<DebugChannel> view() const { return view_; }
  void setView(std::optional<DebugChannel> view) { view_ = view; }
  bool lightsPaused() const { return options_.paused; }
  size_t lightCount() const { return scene_.lights.size(); }
  glm::ivec2 frameSize() const { return {renderer_->width(), renderer_->height()}; }
  const Renderer& renderer() const { return *renderer_; }
  WindowContext& window() { return window_; }

 private:
  using Clock = std::chrono::steady_clock;

  void installCallbacks();
  void flyFromHeldKeys(float seconds);
  void animateLights(float seconds);
  void setLightCount(size_t count);
  void attachPresentSource();
  void present();
  void updateTitle();
  void recordTimings(double frameMs);

  ViewerOptions options_;
  WindowContext window_;  // declared first: every GL object below goes while its context still exists
  ShaderLibrary shaders_;
  Scene scene_;  // lights at rest; the animation moves copies of them
  OrbitCamera camera_;
  std::unique_ptr<Renderer> renderer_;
  std::unique_ptr<Framebuffer> presentSource_;  // wraps the renderer's LDR texture for the blit to the window
  Profiler profiler_;
  std::optional<DebugChannel> view_;  // the final frame when empty; V steps through kDebugChannels
  float lightTime_ = 0.0f;  // seconds of animation so far
  std::vector<PointLight> movedLights_;
  glm::ivec2 pendingSize_{0};
  bool dragging_ = false;
  glm::dvec2 lastCursor_{0.0};
  int framesRendered_ = 0;
  int screenshotsSaved_ = 0;
  Clock::time_point lastFrame_, lastTitle_;
  // Warm frames only: a frame after a change of model, culling, view, light count or size compiles shaders and
  // resizes lists, so timings restart two frames after any change.
  std::deque<FrameTiming> warmTimings_;
  std::deque<double> warmFrameMs_;  // wall time between presented warm frames
  std::string lastConfiguration_;
  int warmFrom_ = 0;  // the first profiler frame counted as warm
};

}  // namespace pbr
