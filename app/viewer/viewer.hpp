#pragma once
#include <chrono>
#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "app/viewer/orbit_camera.hpp"
#include "app/viewer/pass_history.hpp"
#include "renderer/renderer.hpp"
#include "core/scene/builtin_scenes.hpp"
#include "app/viewer/window_context.hpp"

namespace pbr {

// What the window shows: the final frame (no channel) or one of kDebugChannels, as `pbr render --debug`.
const char* viewName(const std::optional<DebugChannel>& view);  // "final" or the channel's name

struct ViewerOptions {
  std::string sceneName = "default";  // built-in name or scene file, re-resolved when the light count changes
  SceneParams sceneParams;
  glm::ivec2 size{1280, 720};  // window size
  FrameOptions frame;          // model, culling, exposure at start
  bool paused = false;         // light animation, or the glTF animation the scene plays
  std::string screenshot;      // F12 and the end of a --quit-after run write here; empty: F12 numbers its files
  bool screenshotOverlay = false;  // screenshots show the window, overlay included, rather than the frame alone
  std::string timing = "auto";
  bool overlay = true;             // the Dear ImGui overlay (--no-ui hides it)
  std::string environmentFolder;   // the overlay's .hdr picker; empty: the current environment's folder
};

class Overlay;

// One line per key or gesture of the viewer, as `pbr view --help` and the overlay list them.
struct KeyHelp {
  std::string keys;
  std::string action;
};
const std::vector<KeyHelp>& viewerKeys();

// An interactive window over the same Renderer as the headless path: an orbit camera, runtime switches of the
// shading model, culling and debug view, animated lights, and an overlay of pass times, light statistics and
// controls (or, without it, the times in the title). Keys and the overlay's widgets change the view through the
// same handlers below.
class Viewer {
 public:
  Viewer(const ViewerOptions& options, Scene scene);
  ~Viewer();
  Viewer(const Viewer&) = delete;
  Viewer& operator=(const Viewer&) = delete;

  // Renders until the window closes, or `frames` frames when > 0 and then writes the screenshot if one was named.
  void run(int frames);
  // One frame: pending resize, held fly keys, light animation, render, present, title, events.
  void frame();
  // The action of one key press (a GLFW key code), as the window's key callback calls it; other keys do nothing.
  void handleKey(int key);

  // The handlers of the keys and the overlay's widgets.
  void setModel(ShadingModel model) { options_.frame.model = model; }
  void setVariant(const ShadingVariant& variant) { options_.frame.variant = variant; }
  void setCulling(Culling culling) { options_.frame.culling = culling; }
  void setShadows(const ShadowSettings& shadows) { options_.frame.shadows = shadows; }
  void setTransparency(Transparency transparency) { options_.frame.transparency = transparency; }
  void setLobes(const MaterialLobes& lobes) { options_.frame.lobes = lobes; }
  void setToneCurve(ToneCurve curve) { options_.frame.toneCurve = curve; }
  void setView(std::optional<DebugChannel> view) { view_ = view; }
  // A fixed exposure, which turns the automatic one off.
  void setExposure(float exposure) {
    options_.frame.exposure = exposure;
    options_.frame.autoExposure = false;
  }
  // The automatic exposure: switched on, it adapts from the exposure shown (kAdapt*EvPerSecond).
  void setAutoExposure(bool on);
  // What the automatic exposure metered, sampled with the light statistics; none while it is off.
  const std::optional<MeteredExposure>& meteredExposure() const { return metered_; }
  void setPaused(bool paused) { options_.paused = paused; }
  // Poses the glTF models that play an animation (a scene loaded with GltfSelection::playable) at `seconds`,
  // wrapped into the animation's length; a pose the file makes malformed stops the animation with a line on stderr.
  void setAnimationTime(double seconds);
  void setGpuCounters(bool on) { options_.frame.stats = on; }
  // New random lights of the scene's own generator, as `--lights count` would have made them; a scene that cannot
  // (a file without random_lights) keeps its lights and says why on stderr.
  void setLightCount(size_t count);
  // "none", "sky" or a Radiance .hdr file: rebuilds the renderer around the new environment (meshes upload and
  // programs compile again). A file that cannot be used keeps the old environment; the message is returned.
  std::string setEnvironment(const std::string& choice);
  void orbit(float yawDelta, float pitchDelta) { camera_.orbit(yawDelta, pitchDelta); }
  void zoom(float factor) { camera_.zoom(factor); }
  // A scene file `pbr render --scene` shows this frame with (scene_snapshot.hpp); throws SceneError when it
  // cannot be written.
  void saveScene(const std::string& path) const;
  // Rebuilds what the frame size owns (G-buffer, HDR and LDR targets, cluster grid) at `width` x `height`; the
  // scene's uploads, IBL maps and compiled programs stay.
  void resize(int width, int height);

  ImageRgba8 screenshot() const;  // the renderer's frame, without the overlay, rows top-down
  void saveScreenshot(const std::string& path) const;
  // F12 and the end of a --quit-after run: the frame now, or with screenshotOverlay the window as the next frame
  // presents it.
  void takeScreenshot(const std::string& path);

  const FrameOptions& frameOptions() const { return options_.frame; }
  const ViewerOptions& options() const { return options_; }
  std::optional<DebugChannel> view() const { return view_; }
  bool lightsPaused() const { return options_.paused; }
  // Whether glTF models play an animation (then P pauses it, and the lights move only as it moves them).
  bool playsAnimation() const { return !scene_.gltfPlayback.empty(); }
  double animationTime() const { return animationTime_; }
  double animationDuration() const;  // the longest of the animations played, in seconds
  size_t lightCount() const { return scene_.lights.size(); }
  const Scene& scene() const { return scene_; }
  // The material extensions' lobes the scene's materials use (usedLobes), which the overlay offers to switch off.
  const MaterialLobes& usedLobes() const { return usedLobes_; }
  const MaterialLobes& lobes() const { return options_.frame.lobes; }
  const OrbitCamera& camera() const { return camera_; }
  glm::ivec2 frameSize() const { return {renderer_->width(), renderer_->height()}; }
  const Renderer& renderer() const { return *renderer_; }
  TimingMode timingMode() const { return profiler_.mode(); }
  WindowContext& window() { return window_; }
  const Overlay* overlay() const { return overlay_.get(); }
  const PassHistory& passHistory() const { return passHistory_; }
  // The renderer's light statistics, read at most every quarter second while the overlay shows them: reading
  // them waits for the GPU.
  const LightStats& lightStats() const { return lightStats_; }
  int framesRendered() const { return framesRendered_; }

 private:
  using Clock = std::chrono::steady_clock;

  void installCallbacks();
  void flyFromHeldKeys(float seconds);
  void animateLights(float seconds);
  void attachPresentSource();
  void present();
  ImageRgba8 readWindow() const;
  void updateTitle();
  void recordTimings(double frameMs);
  void sampleLightStats();

  ViewerOptions options_;
  WindowContext window_;  // declared first: every GL object below goes while its context still exists
  ShaderLibrary shaders_;
  Scene scene_;  // lights at rest; the animation moves copies of them
  MaterialLobes usedLobes_;
  OrbitCamera camera_;
  std::unique_ptr<Renderer> renderer_;
  std::unique_ptr<Framebuffer> presentSource_;  // wraps the renderer's LDR texture for the blit to the window
  Profiler profiler_;
  std::unique_ptr<Overlay> overlay_;  // after the callbacks it chains to, before the context goes
  std::optional<DebugChannel> view_;  // the final frame when empty; V steps through kDebugChannels
  float lightTime_ = 0.0f;  // seconds of animation so far
  double animationTime_ = 0.0;  // the glTF animation's time, when the scene plays one
  std::vector<PointLight> movedLights_;
  glm::ivec2 pendingSize_{0};
  bool dragging_ = false;
  glm::dvec2 lastCursor_{0.0};
  int framesRendered_ = 0;
  int screenshotsSaved_ = 0;
  std::string pendingWindowShot_;  // saved from the back buffer once the next frame's overlay is drawn
  bool unattendedShot_ = false;    // that shot ends a --quit-after run: a failure is the run's error
  std::string windowShotError_;
  Clock::time_point lastFrame_, lastTitle_, lastStats_;
  PassHistory passHistory_;  // every frame's pass times, warm or not: the graph shows what a change costs
  LightStats lightStats_;
  std::optional<MeteredExposure> metered_;
  // Warm frames only: a frame after a change of model, variant, culling, view, light count, environment, shadow
  // settings or size
  // compiles shaders and resizes lists, so timings restart two frames after any change.
  std::deque<FrameTiming> warmTimings_;
  std::deque<double> warmFrameMs_;  // wall time between presented warm frames
  std::string lastConfiguration_;
  int warmFrom_ = 0;  // the first profiler frame counted as warm
};

}  // namespace pbr
