// Keyboard and mouse: every key press goes through Viewer::handleKey; held WASD/QE keys and the mouse move the
// orbit camera.
#include "app/viewer/viewer.hpp"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>

#include "app/scene_source.hpp"
#include "app/viewer/overlay.hpp"

namespace pbr {

namespace {

constexpr float kExposureStep = 1.41421356f;  // half a stop per key press
constexpr float kOrbitRadiansPerPixel = 0.005f;
constexpr float kZoomPerScrollStep = 0.9f;
constexpr float kFlyDistancesPerSecond = 0.5f;  // in units of the distance to the orbit target
constexpr size_t kMaxLights = size_t(1) << 20;  // the scene parameters' limit

Viewer& viewerOf(GLFWwindow* window) { return *static_cast<Viewer*>(glfwGetWindowUserPointer(window)); }

}  // namespace

const std::vector<KeyHelp>& viewerKeys() {
  static const std::vector<KeyHelp> keys = {
      {"drag, scroll", "orbit, zoom"},
      {"W/A/S/D/Q/E", "fly"},
      {"M", "Blinn-Phong / PBR"},
      {"C", "culling: auto / clustered / brute force"},
      {"V", "debug view: final, then " + debugChannelNames(", ")},
      {"+ / -", "exposure by half a stop (turns the automatic exposure off)"},
      {"X", "automatic exposure on / off (metered from the frame, adapting 3 EV/s brighter, 1 EV/s darker)"},
      {"T", "tone curve: the next of aces-hill, aces-narkowicz, khronos-neutral, agx, reinhard, exponential, "
            "linear"},
      {"[ / ]", "halve / double the lights"},
      {"P", "pause the lights, or the glTF animation the scene plays"},
      {"F12", "screenshot"},
      {"Esc", "quit"},
  };
  return keys;
}

void Viewer::installCallbacks() {
  GLFWwindow* w = window_.window();
  glfwSetWindowUserPointer(w, this);
  // The overlay chains these callbacks behind its own and asks for the input that lands on its widgets.
  glfwSetKeyCallback(w, [](GLFWwindow* window, int key, int, int action, int) {
    Viewer& v = viewerOf(window);
    if (v.overlay_ && v.overlay_->wantsKeyboard()) return;
    if (action == GLFW_PRESS || action == GLFW_REPEAT) v.handleKey(key);
  });
  glfwSetFramebufferSizeCallback(w, [](GLFWwindow* window, int width, int height) {
    viewerOf(window).pendingSize_ = {width, height};
  });
  glfwSetMouseButtonCallback(w, [](GLFWwindow* window, int button, int action, int) {
    if (button != GLFW_MOUSE_BUTTON_LEFT) return;
    Viewer& v = viewerOf(window);
    v.dragging_ = action == GLFW_PRESS && !(v.overlay_ && v.overlay_->wantsMouse());
    glfwGetCursorPos(window, &v.lastCursor_.x, &v.lastCursor_.y);
  });
  glfwSetCursorPosCallback(w, [](GLFWwindow* window, double x, double y) {
    Viewer& v = viewerOf(window);
    if (!v.dragging_) return;
    const glm::dvec2 delta = glm::dvec2(x, y) - v.lastCursor_;
    v.lastCursor_ = {x, y};
    // Dragging right turns the scene right, dragging down tilts it towards the viewer.
    v.orbit(-static_cast<float>(delta.x) * kOrbitRadiansPerPixel, static_cast<float>(delta.y) * kOrbitRadiansPerPixel);
  });
  glfwSetScrollCallback(w, [](GLFWwindow* window, double, double y) {
    Viewer& v = viewerOf(window);
    if (v.overlay_ && v.overlay_->wantsMouse()) return;
    v.zoom(std::pow(kZoomPerScrollStep, static_cast<float>(y)));
  });
}

void Viewer::flyFromHeldKeys(float seconds) {
  if (overlay_ && overlay_->wantsKeyboard()) return;
  GLFWwindow* w = window_.window();
  const auto held = [w](int key) { return glfwGetKey(w, key) == GLFW_PRESS ? 1.0f : 0.0f; };
  const glm::vec3 direction(held(GLFW_KEY_D) - held(GLFW_KEY_A), held(GLFW_KEY_E) - held(GLFW_KEY_Q),
                            held(GLFW_KEY_W) - held(GLFW_KEY_S));
  if (direction != glm::vec3(0.0f)) camera_.fly(direction * (kFlyDistancesPerSecond * seconds));
}

void Viewer::handleKey(int key) {
  const FrameOptions& f = options_.frame;
  switch (key) {
    case GLFW_KEY_M:
      setModel(f.model == ShadingModel::Pbr ? ShadingModel::BlinnPhong : ShadingModel::Pbr);
      break;
    case GLFW_KEY_T: {
      const auto* next = std::find(std::begin(kToneCurves), std::end(kToneCurves), f.toneCurve) + 1;
      setToneCurve(next == std::end(kToneCurves) ? kToneCurves[0] : *next);
      break;
    }
    case GLFW_KEY_C:
      setCulling(f.culling == Culling::Auto ? Culling::Clustered
                 : f.culling == Culling::Clustered ? Culling::None : Culling::Auto);
      break;
    case GLFW_KEY_V: {  // final -> each debug channel in turn -> final
      const auto next = view_ ? std::find(kDebugChannels.begin(), kDebugChannels.end(), *view_) + 1
                              : kDebugChannels.begin();
      setView(next == kDebugChannels.end() ? std::nullopt : std::optional<DebugChannel>(*next));
      break;
    }
    case GLFW_KEY_X:
      setAutoExposure(!f.autoExposure);
      break;
    case GLFW_KEY_EQUAL:
    case GLFW_KEY_KP_ADD:
      setExposure(f.exposure * kExposureStep);
      break;
    case GLFW_KEY_MINUS:
    case GLFW_KEY_KP_SUBTRACT:
      setExposure(f.exposure / kExposureStep);
      break;
    case GLFW_KEY_LEFT_BRACKET:
      setLightCount(std::max<size_t>(lightCount() / 2, 1));
      break;
    case GLFW_KEY_RIGHT_BRACKET:
      setLightCount(std::min(std::max<size_t>(lightCount() * 2, 1), kMaxLights));
      break;
    case GLFW_KEY_P:
      setPaused(!options_.paused);
      break;
    case GLFW_KEY_F12:
      takeScreenshot(options_.screenshot.empty() ? "pbr-view-" + std::to_string(++screenshotsSaved_) + ".png"
                                                 : options_.screenshot);
      break;
    case GLFW_KEY_ESCAPE:
      glfwSetWindowShouldClose(window_.window(), GLFW_TRUE);
      break;
    default:
      break;
  }
}

void Viewer::setLightCount(size_t count) {
  try {
    SceneParams params = options_.sceneParams;
    params.lights = static_cast<int>(count);
    Scene regenerated = resolveScene(options_.sceneName, params);
    renderer_->setLights(regenerated.lights);
    scene_.lights = std::move(regenerated.lights);
    options_.sceneParams = params;
    movedLights_ = scene_.lights;
    if (lightTime_ > 0.0f) animateLights(0.0f);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pbr view: cannot change the light count to %zu: %s\n", count, e.what());
  }
}

}  // namespace pbr
