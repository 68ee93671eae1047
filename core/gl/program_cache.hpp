#pragma once
#include <cstddef>
#include <map>
#include <string>

#include "core/gl/shader_library.hpp"

namespace pbr {

// Linked programs by their files and defines, compiled on first request and kept for as long as the cache lives.
// The frame's scene-lifetime resources own one, so that objects rebuilt more often (the size-dependent targets and
// the cluster grid) find their programs compiled already. References stay valid for the cache's lifetime.
class ProgramCache {
 public:
  explicit ProgramCache(const ShaderLibrary& library) : library_(library) {}
  ProgramCache(const ProgramCache&) = delete;
  ProgramCache& operator=(const ProgramCache&) = delete;

  const Program& compute(const std::string& file, const ShaderDefines& defines = {});
  const Program& graphics(const std::string& vertexFile, const std::string& fragmentFile,
                          const ShaderDefines& defines = {});

  const ShaderLibrary& library() const { return library_; }
  size_t compiled() const { return programs_.size(); }  // programs compiled so far: every request that missed

 private:
  const ShaderLibrary& library_;
  std::map<std::string, Program> programs_;  // "files|defines" -> program
};

}  // namespace pbr
