#include "core/io/context_info.hpp"

#include <stdexcept>

namespace pbr {

EglPlatform parseEglPlatform(const std::string& name) {
  if (name == "auto") return EglPlatform::Auto;
  if (name == "surfaceless") return EglPlatform::Surfaceless;
  if (name == "device") return EglPlatform::Device;
  throw std::invalid_argument("unknown EGL platform '" + name + "' (expected auto, surfaceless or device)");
}

const char* toString(EglPlatform platform) {
  switch (platform) {
    case EglPlatform::Auto: return "auto";
    case EglPlatform::Surfaceless: return "surfaceless";
    case EglPlatform::Device: return "device";
  }
  return "?";
}

bool isSoftwareRenderer(const std::string& r) {
  return r.find("llvmpipe") != std::string::npos || r.find("softpipe") != std::string::npos;
}

}  // namespace pbr
