#pragma once
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace pbr {

struct ShaderDefine {
  std::string name;
  std::string value;
  bool binding = false;  // a binding point's index (binding_table.hpp): where, not which permutation
};
using ShaderDefines = std::vector<ShaderDefine>;
// "NAME=value\n" for each define in order: equal keys compile the same source, so it keys program caches.
std::string definesKey(const ShaderDefines& defines);

// The label a program gets (core/gl/gl_objects.hpp: labelObject): its files and the defines that choose its
// permutation, switches on by name, other values as NAME=value, binding points and switches off left out:
// "lighting/deferred.comp [VISIBILITY_EXACT ... HDR_IMAGE_FORMAT=rgba16f CLUSTERED]".
std::string programLabel(const std::string& files, const ShaderDefines& defines);

// Expansion, compile and link failures, with every log line mapped back to "file:line: message" of the original
// file.
class ShaderError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// One GLSL translation unit after #include resolution: `files[i]` is the file behind `#line n i`.
struct ExpandedShader {
  std::string text;
  std::vector<std::string> files;
};

// GLSL sources from a directory tree, as text (no GL): resolves `#include "path"` (relative to the including file,
// then to the root; each file once) and injects `#define`s after `#version`. The shader library
// (core/gl/shader_library.hpp) compiles what it expands.
class ShaderSources {
 public:
  // PBR_SHADER_DIR in the environment, else the source tree's shaders/ folder.
  static std::filesystem::path defaultRoot();

  explicit ShaderSources(std::filesystem::path root = defaultRoot());
  const std::filesystem::path& root() const { return root_; }

  ExpandedShader expand(const std::string& file, const ShaderDefines& defines = {}) const;
  ExpandedShader expandSource(const std::string& name, const std::string& text,
                              const ShaderDefines& defines = {}) const;

 private:
  std::filesystem::path root_;
};

// Rewrites a driver's compile log (Mesa "0:12(5): ..." or NVIDIA "0(12) : ...") to "file:line: ...".
std::string remapShaderLog(const std::string& log, const std::vector<std::string>& files);

}  // namespace pbr
