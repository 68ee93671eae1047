#pragma once
#include <filesystem>
#include <string>
#include <utility>

#include "core/gl/gl_objects.hpp"
#include "core/scene/shader_sources.hpp"

namespace pbr {

// Compiles programs from the GLSL its sources expand (core/scene/shader_sources.hpp); compile and link failures
// throw ShaderError with the driver's log mapped back to the original files (remapShaderLog).
class ShaderLibrary : public ShaderSources {
 public:
  explicit ShaderLibrary(std::filesystem::path root = defaultRoot()) : ShaderSources(std::move(root)) {}

  Program compute(const std::string& file, const ShaderDefines& defines = {}) const;
  Program computeFromSource(const std::string& name, const std::string& text, const ShaderDefines& defines = {}) const;
  Program graphics(const std::string& vertexFile, const std::string& fragmentFile,
                   const ShaderDefines& defines = {}) const;
};

}  // namespace pbr
