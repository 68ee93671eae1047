#include <glad/egl.h>

#include <cstring>
#include <string>
#include <vector>

#include "core/gl/context.hpp"

namespace pbr {
namespace {

bool hasExtension(const char* list, const char* name) {
  if (!list) return false;
  const size_t len = std::strlen(name);
  for (const char* p = list; (p = std::strstr(p, name)) != nullptr; p += len) {
    const bool startOk = p == list || p[-1] == ' ';
    const bool endOk = p[len] == ' ' || p[len] == '\0';
    if (startOk && endOk) return true;
  }
  return false;
}

std::string eglErrorName(EGLint error) {
  switch (error) {
    case EGL_SUCCESS: return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
    case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
    case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
    default: return "EGL error " + std::to_string(error);
  }
}

// The device platform lists every device of every installed vendor; Mesa's software device is only a
// fallback behind any hardware device.
EGLDeviceEXT pickDevice(bool& isSoftware) {
  EGLint count = 0;
  if (!eglQueryDevicesEXT || !eglQueryDevicesEXT(0, nullptr, &count) || count <= 0) return EGL_NO_DEVICE_EXT;
  std::vector<EGLDeviceEXT> devices(static_cast<size_t>(count));
  eglQueryDevicesEXT(count, devices.data(), &count);
  for (EGLint i = 0; i < count; ++i) {
    const char* ext = eglQueryDeviceStringEXT ? eglQueryDeviceStringEXT(devices[i], EGL_EXTENSIONS) : nullptr;
    if (!hasExtension(ext, "EGL_MESA_device_software")) {
      isSoftware = false;
      return devices[i];
    }
  }
  isSoftware = true;
  return devices[0];
}

class EglContext final : public Context {
 public:
  explicit EglContext(EglPlatform requested) {
    if (!gladLoaderLoadEGL(EGL_NO_DISPLAY)) throw ContextError("libEGL could not be loaded");
    const char* clientExt = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    const bool haveSurfaceless = hasExtension(clientExt, "EGL_MESA_platform_surfaceless");
    const bool haveDevice = hasExtension(clientExt, "EGL_EXT_platform_device");

    bool deviceIsSoftware = true;
    EGLDeviceEXT device = haveDevice ? pickDevice(deviceIsSoftware) : EGL_NO_DEVICE_EXT;

    EglPlatform platform = requested;
    if (platform == EglPlatform::Auto) {
      if (device != EGL_NO_DEVICE_EXT && !deviceIsSoftware) platform = EglPlatform::Device;
      else if (haveSurfaceless) platform = EglPlatform::Surfaceless;
      else platform = EglPlatform::Device;
    }

    // EGL 1.5's entry point where the client library offers it, the EXT one of EGL 1.4 otherwise.
    auto platformDisplay = [](EGLenum kind, void* native) {
      return eglGetPlatformDisplay ? eglGetPlatformDisplay(kind, native, nullptr)
                                   : eglGetPlatformDisplayEXT(kind, native, nullptr);
    };
    if (platform == EglPlatform::Surfaceless) {
      if (!haveSurfaceless) throw ContextError("EGL_MESA_platform_surfaceless is not available");
      display_ = platformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY);
    } else {
      if (device == EGL_NO_DEVICE_EXT) throw ContextError("no EGL device found (EGL_EXT_platform_device)");
      display_ = platformDisplay(EGL_PLATFORM_DEVICE_EXT, device);
    }
    if (display_ == EGL_NO_DISPLAY) throw ContextError("eglGetPlatformDisplay failed: " + eglErrorName(eglGetError()));

    EGLint major = 0, minor = 0;
    if (!eglInitialize(display_, &major, &minor)) {
      throw ContextError("eglInitialize failed: " + eglErrorName(eglGetError()));
    }
    // Reload with the display so that display extensions and EGL 1.5 entry points resolve.
    gladLoaderLoadEGL(display_);
    if (!eglBindAPI(EGL_OPENGL_API)) throw ContextError("eglBindAPI(EGL_OPENGL_API) failed");

    const EGLint configAttribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint numConfigs = 0;
    const bool noConfig = hasExtension(eglQueryString(display_, EGL_EXTENSIONS), "EGL_KHR_no_config_context");
    if (!noConfig && (!eglChooseConfig(display_, configAttribs, &config, 1, &numConfigs) || numConfigs == 0)) {
      throw ContextError("no EGL config supports OpenGL");
    }

    const bool debug = glDebugRequested();
    const EGLint contextAttribs[] = {EGL_CONTEXT_MAJOR_VERSION, 4,
                                     EGL_CONTEXT_MINOR_VERSION, 5,
                                     EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                     EGL_CONTEXT_OPENGL_DEBUG, debug ? EGL_TRUE : EGL_FALSE,
                                     EGL_NONE};
    context_ = eglCreateContext(display_, noConfig ? EGL_NO_CONFIG_KHR : config, EGL_NO_CONTEXT, contextAttribs);
    if (context_ == EGL_NO_CONTEXT) {
      const std::string err = eglErrorName(eglGetError());
      eglTerminate(display_);
      throw ContextError("could not create an OpenGL 4.5 core context: " + err);
    }
    makeCurrent();
    initializeGl(platform == EglPlatform::Surfaceless ? "egl-surfaceless" : "egl-device",
                 reinterpret_cast<void* (*)(const char*)>(eglGetProcAddress), debug);
  }

  ~EglContext() override {
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display_, context_);
    eglTerminate(display_);
  }

  void makeCurrent() override {
    if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) {
      throw ContextError("eglMakeCurrent failed: " + eglErrorName(eglGetError()));
    }
  }

  void swapBuffers() override {}

 private:
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
};

}  // namespace

std::unique_ptr<Context> createHeadlessContext(EglPlatform platform) {
  return std::make_unique<EglContext>(platform);
}

}  // namespace pbr
