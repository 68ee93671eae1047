#include "app/viewer/viewer.hpp"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>

#include "app/viewer/overlay.hpp"
#include "app/viewer/scene_snapshot.hpp"
#include "core/gl/readback.hpp"
#include "core/io/image_output.hpp"
#include "core/scene/exposure.hpp"
#include "core/scene/gltf_loader.hpp"

namespace pbr {

namespace {
constexpr float kLightOrbitRadiansPerSecond = 0.3f;
// A slow frame (shader compilation, a software rasterizer) must not jump the camera or the lights.
constexpr float kMaxStepSeconds = 0.1f;
constexpr double kStatsIntervalMs = 250.0;  // live to the eye, and the GPU waited for only four times a second
}  // namespace

const char* viewName(const std::optional<DebugChannel>& view) { return view ? toString(*view) : "final"; }

Viewer::Viewer(const ViewerOptions& options, Scene scene)
    : options_(options),
      window_(options.size.x, options.size.y, "pbr view"),
      scene_(std::move(scene)),
      usedLobes_(pbr::usedLobes(scene_)),
      camera_(scene_.camera),
      profiler_(chooseTimingMode(options.timing, window_.info().renderer)),
      movedLights_(scene_.lights) {
  const glm::ivec2 size = window_.framebufferSize();
  renderer_ = std::make_unique<Renderer>(shaders_, scene_, size.x, size.y, measuredGrid());
  attachPresentSource();
  pendingSize_ = size;
  installCallbacks();
  if (options_.overlay) overlay_ = std::make_unique<Overlay>(window_.window());
  lastFrame_ = lastTitle_ = lastStats_ = Clock::now();
  // The scene was posed at the chosen time (GltfSelection::time, 0 by default); playing goes on from there.
  animationTime_ = options_.sceneParams.gltfSelection.time.value_or(0.0);
}

double Viewer::animationDuration() const {
  double longest = 0.0;
  for (const std::shared_ptr<const GltfPlayback>& p : scene_.gltfPlayback) longest = std::max(longest, p->duration);
  return longest;
}

void Viewer::setAnimationTime(double seconds) {
  if (!playsAnimation()) return;
  const double length = animationDuration();
  animationTime_ = length > 0.0 ? seconds - length * std::floor(seconds / length) : 0.0;
  try {
    renderer_->scenePosed(posePlayback(scene_, animationTime_));
  } catch (const SceneError& e) {
    std::fprintf(stderr, "pbr view: the animation stops at %.3f s: %s\n", animationTime_, e.what());
    scene_.gltfPlayback.clear();
  }
}

Viewer::~Viewer() = default;

void Viewer::resize(int width, int height) {
  presentSource_.reset();
  renderer_->resize(width, height);
  attachPresentSource();
  pendingSize_ = {width, height};
}

void Viewer::attachPresentSource() {
  presentSource_ = std::make_unique<Framebuffer>("viewer.present");
  presentSource_->attach(GL_COLOR_ATTACHMENT0, renderer_->ldr());
  presentSource_->checkComplete();
}

void Viewer::run(int frames) {
  const bool shotAtEnd = frames > 0 && !options_.screenshot.empty();
  while (!window_.shouldClose() && (frames <= 0 || framesRendered_ < frames)) {
    // The window's picture is taken while the last frame presents; the frame alone is still there afterwards.
    if (shotAtEnd && options_.screenshotOverlay && framesRendered_ == frames - 1) {
      pendingWindowShot_ = options_.screenshot;
      unattendedShot_ = true;
    }
    frame();
  }
  checkGlError("the viewer");
  // An unattended run's screenshot is its result: a failed write ends the command with an error.
  if (shotAtEnd && !options_.screenshotOverlay) {
    saveScreenshot(options_.screenshot);
    std::printf("wrote %s\n", options_.screenshot.c_str());
  }
  if (!windowShotError_.empty()) throw std::runtime_error(windowShotError_);
}

void Viewer::frame() {
  glfwPollEvents();
  if (pendingSize_.x <= 0 || pendingSize_.y <= 0) {  // minimised: nothing to draw into until it comes back
    glfwWaitEventsTimeout(0.1);
    return;
  }
  if (pendingSize_ != frameSize()) resize(pendingSize_.x, pendingSize_.y);

  const Clock::time_point now = Clock::now();
  const double frameMs = std::chrono::duration<double, std::milli>(now - lastFrame_).count();
  lastFrame_ = now;
  const float step = std::min(static_cast<float>(frameMs / 1000.0), kMaxStepSeconds);
  flyFromHeldKeys(step);
  if (!options_.paused && playsAnimation()) {
    setAnimationTime(animationTime_ + step);
  } else if (!options_.paused) {
    animateLights(step);
  }

  renderer_->setCamera(camera_.camera());
  FrameOptions frameOptions = options_.frame;
  frameOptions.debug = view_;
  // The first frame meters at once; later ones adapt over the time they show.
  frameOptions.adaptSeconds = framesRendered_ == 0 ? std::numeric_limits<float>::infinity() : step;
  renderer_->renderFrame(frameOptions, profiler_);
  ++framesRendered_;
  recordTimings(frameMs);
  if (overlay_ || options_.frame.autoExposure) sampleLightStats();
  present();
  updateTitle();
}

void Viewer::sampleLightStats() {
  const Clock::time_point now = Clock::now();
  if (std::chrono::duration<double, std::milli>(now - lastStats_).count() < kStatsIntervalMs) return;
  lastStats_ = now;
  if (overlay_) lightStats_ = renderer_->lightStats();
  // The exposure shown follows the meter, so that switching it off, saving the scene or a screenshot keeps it.
  metered_ = options_.frame.autoExposure ? renderer_->meteredExposure() : std::nullopt;
  if (metered_) options_.frame.exposure = float(exposureFromEv100(metered_->ev100));
}

void Viewer::setAutoExposure(bool on) {
  if (on && !options_.frame.autoExposure && framesRendered_ > 0) renderer_->restartExposure(options_.frame.exposure);
  options_.frame.autoExposure = on;
  if (!on) metered_.reset();
}

void Viewer::recordTimings(double frameMs) {
  constexpr size_t kWindow = 60;  // frames in the medians: a second or two at interactive rates
  const FrameOptions& f = options_.frame;
  const glm::ivec2 size = frameSize();
  const std::string configuration = std::string(toString(f.model)) + toString(f.variant) + toString(f.culling) +
                                    viewName(view_) + std::to_string(lightCount()) + "@" + std::to_string(size.x) +
                                    "x" + std::to_string(size.y) + (f.stats ? " counters " : " ") +
                                    (scene_.environment ? scene_.environment->file + "|" : "none") + " shadows " +
                                    toString(f.shadows.mode) + toString(f.shadows.filter) + toString(f.toneCurve) +
                                    std::to_string(f.shadows.atlasSize);
  const int thisFrame = framesRendered_ - 1;
  if (configuration != lastConfiguration_) {
    lastConfiguration_ = configuration;
    lastStats_ = Clock::time_point{};  // the overlay's light statistics follow a change at once
    warmFrom_ = thisFrame + 2;
    warmTimings_.clear();
    warmFrameMs_.clear();
  }
  if (thisFrame >= warmFrom_) warmFrameMs_.push_back(frameMs);
  for (FrameTiming& t : profiler_.takeResults(false)) {
    passHistory_.add(t);
    if (t.frame >= warmFrom_) warmTimings_.push_back(std::move(t));
  }
  while (warmTimings_.size() > kWindow) warmTimings_.pop_front();
  while (warmFrameMs_.size() > kWindow) warmFrameMs_.pop_front();
}

// The overlay is drawn over the blitted frame in the window's own framebuffer, after the profiler's frame has
// ended: it is in no pass's time and in no screenshot of the frame alone.
void Viewer::present() {
  const glm::ivec2 size = frameSize();
  const glm::ivec2 target = window_.framebufferSize();
  glBlitNamedFramebuffer(presentSource_->id(), 0, 0, 0, size.x, size.y, 0, 0, target.x, target.y,
                         GL_COLOR_BUFFER_BIT, GL_NEAREST);
  if (overlay_) overlay_->draw(*this);
  if (!pendingWindowShot_.empty()) {
    const std::string path = std::move(pendingWindowShot_);
    pendingWindowShot_.clear();
    try {
      writeLdr(path, readWindow());
      std::printf("wrote %s\n", path.c_str());
    } catch (const std::exception& e) {
      if (unattendedShot_) {
        windowShotError_ = e.what();  // run() ends with it
      } else {
        std::fprintf(stderr, "pbr view: %s\n", e.what());
      }
    }
  }
  window_.swapBuffers();
}

ImageRgba8 Viewer::readWindow() const {
  const glm::ivec2 size = window_.framebufferSize();
  ImageRgba8 image;
  image.width = size.x;
  image.height = size.y;
  image.pixels.resize(size_t(size.x) * size_t(size.y) * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, size.x, size.y, GL_RGBA, GL_UNSIGNED_BYTE, image.pixels.data());
  // GL rows run bottom-up; PNG rows top-down. The window has no alpha to speak of: opaque, as the frame is.
  const size_t row = size_t(size.x) * 4;
  std::vector<uint8_t> flipped(image.pixels.size());
  for (int y = 0; y < size.y; ++y) {
    std::copy_n(image.pixels.begin() + static_cast<std::ptrdiff_t>(size_t(y) * row), row,
                flipped.begin() + static_cast<std::ptrdiff_t>(size_t(size.y - 1 - y) * row));
  }
  for (size_t i = 3; i < flipped.size(); i += 4) flipped[i] = 255;
  image.pixels = std::move(flipped);
  return image;
}

void Viewer::animateLights(float seconds) {
  lightTime_ += seconds;
  // Every light circles the vertical axis through the scene camera's target, all at one angular speed.
  const glm::vec3 centre = scene_.camera.target;
  const float angle = lightTime_ * kLightOrbitRadiansPerSecond;
  const float c = std::cos(angle), s = std::sin(angle);
  for (size_t i = 0; i < scene_.lights.size(); ++i) {
    const glm::vec3 d = scene_.lights[i].position - centre;
    movedLights_[i].position = centre + glm::vec3(c * d.x + s * d.z, d.y, -s * d.x + c * d.z);
  }
  renderer_->setLights(movedLights_);
}

ImageRgba8 Viewer::screenshot() const { return readbackRgba8(renderer_->ldr()); }

void Viewer::saveScreenshot(const std::string& path) const { writeLdr(path, screenshot()); }

void Viewer::takeScreenshot(const std::string& path) {
  if (options_.screenshotOverlay) {
    pendingWindowShot_ = path;
    return;
  }
  try {
    saveScreenshot(path);
    std::printf("wrote %s\n", path.c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pbr view: %s\n", e.what());
  }
}

void Viewer::saveScene(const std::string& path) const {
  writeSceneSnapshot(path, {options_.sceneName, options_.sceneParams, scene_, camera_.camera(),
                            options_.frame.exposure});
}

std::string Viewer::setEnvironment(const std::string& choice) {
  const std::optional<EnvironmentDesc> previous = scene_.environment;
  if (choice == "none") {
    scene_.environment.reset();
  } else {
    // The intensity and rotation of the scene's environment stay with a new image; the sky keeps its own.
    EnvironmentDesc next = previous.value_or(EnvironmentDesc{});
    next.file = choice == "sky" ? "" : choice;
    scene_.environment = next;
  }
  const glm::ivec2 size = frameSize();
  presentSource_.reset();
  renderer_.reset();
  std::string error;
  try {
    renderer_ = std::make_unique<Renderer>(shaders_, scene_, size.x, size.y, measuredGrid());
  } catch (const std::exception& e) {
    error = e.what();
    scene_.environment = previous;
    renderer_ = std::make_unique<Renderer>(shaders_, scene_, size.x, size.y, measuredGrid());
  }
  attachPresentSource();
  renderer_->setLights(movedLights_);
  if (!error.empty()) std::fprintf(stderr, "pbr view: %s\n", error.c_str());
  return error;
}

}  // namespace pbr
