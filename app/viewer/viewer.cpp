#include "app/viewer/viewer.hpp"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/readback.hpp"

namespace pbr {

namespace {
constexpr float kLightOrbitRadiansPerSecond = 0.3f;
// A slow frame (shader compilation, a software rasterizer) must not jump the camera or the lights.
constexpr float kMaxStepSeconds = 0.1f;
}  // namespace

const char* viewName(const std::optional<DebugChannel>& view) { return view ? toString(*view) : "final"; }

Viewer::Viewer(const ViewerOptions& options, Scene scene)
    : options_(options),
      window_(options.size.x, options.size.y, "pbr view"),
      scene_(std::move(scene)),
      camera_(scene_.camera),
      profiler_(chooseTimingMode(options.timing, window_.info().renderer)),
      movedLights_(scene_.lights) {
  const glm::ivec2 size = window_.framebufferSize();
  renderer_ = std::make_unique<Renderer>(shaders_, scene_, size.x, size.y);
  attachPresentSource();
  pendingSize_ = size;
  installCallbacks();
  lastFrame_ = lastTitle_ = Clock::now();
}

void Viewer::resize(int width, int height) {
  presentSource_.reset();
  renderer_->resize(width, height);
  attachPresentSource();
  pendingSize_ = {width, height};
}

void Viewer::attachPresentSource() {
  presentSource_ = std::make_unique<Framebuffer>();
  presentSource_->attach(GL_COLOR_ATTACHMENT0, renderer_->ldr());
  presentSource_->checkComplete();
}

void Viewer::run(int frames) {
  while (!window_.shouldClose() && (frames <= 0 || framesRendered_ < frames)) frame();
  checkGlError("the viewer");
  if (frames > 0 && !options_.screenshot.empty()) {
    saveScreenshot(options_.screenshot);
    std::printf("wrote %s\n", options_.screenshot.c_str());
  }
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
  if (!options_.paused) animateLights(step);

  renderer_->setCamera(camera_.camera());
  FrameOptions frameOptions = options_.frame;
  frameOptions.debug = view_;
  renderer_->renderFrame(frameOptions, profiler_);
  present();
  ++framesRendered_;
  recordTimings(frameMs);
  updateTitle();
}

void Viewer::recordTimings(double frameMs) {
  constexpr size_t kWindow = 60;  // frames in the medians: a second or two at interactive rates
  const FrameOptions& f = options_.frame;
  const glm::ivec2 size = frameSize();
  const std::string configuration = std::string(toString(f.model)) + toString(f.culling) + viewName(view_) +
                                    std::to_string(lightCount()) + "@" + std::to_string(size.x) + "x" +
                                    std::to_string(size.y);
  const int thisFrame = framesRendered_ - 1;
  if (configuration != lastConfiguration_) {
    lastConfiguration_ = configuration;
    warmFrom_ = thisFrame + 2;
    warmTimings_.clear();
    warmFrameMs_.clear();
  }
  if (thisFrame >= warmFrom_) warmFrameMs_.push_back(frameMs);
  for (FrameTiming& t : profiler_.takeResults(false)) {
    if (t.frame >= warmFrom_) warmTimings_.push_back(std::move(t));
  }
  while (warmTimings_.size() > kWindow) warmTimings_.pop_front();
  while (warmFrameMs_.size() > kWindow) warmFrameMs_.pop_front();
}

void Viewer::present() {
  const glm::ivec2 size = frameSize();
  const glm::ivec2 target = window_.framebufferSize();
  glBlitNamedFramebuffer(presentSource_->id(), 0, 0, 0, size.x, size.y, 0, 0, target.x, target.y,
                         GL_COLOR_BUFFER_BIT, GL_NEAREST);
  window_.swapBuffers();
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

void Viewer::saveScreenshot(const std::string& path) const { writePng(path, screenshot()); }

}  // namespace pbr
