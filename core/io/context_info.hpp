#pragma once
#include <string>

// What a run says of its OpenGL context, with no GL: the platform asked for, the driver's strings, and whether they
// name a CPU rasterizer. The contexts themselves are core/gl/context.hpp's.
namespace pbr {

// Which EGL platform a headless context is made on. Auto picks a hardware device when the
// device platform offers one and Mesa's surfaceless platform otherwise.
enum class EglPlatform { Auto, Surfaceless, Device };

EglPlatform parseEglPlatform(const std::string& name);
const char* toString(EglPlatform platform);

struct ContextInfo {
  std::string platform;  // "egl-surfaceless", "egl-device", "glfw"
  std::string renderer;  // GL_RENDERER
  std::string version;   // GL_VERSION
  std::string vendor;    // GL_VENDOR
};

// Mesa's CPU rasterizers (llvmpipe, softpipe) by their GL_RENDERER string.
bool isSoftwareRenderer(const std::string& glRenderer);

}  // namespace pbr
