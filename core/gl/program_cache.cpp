#include "core/gl/program_cache.hpp"

namespace pbr {

const Program& ProgramCache::compute(const std::string& file, const ShaderDefines& defines) {
  const std::string key = file + "|" + definesKey(defines);
  auto it = programs_.find(key);
  if (it == programs_.end()) it = programs_.emplace(key, library_.compute(file, defines)).first;
  return it->second;
}

const Program& ProgramCache::graphics(const std::string& vertexFile, const std::string& fragmentFile,
                                      const ShaderDefines& defines) {
  const std::string key = vertexFile + "+" + fragmentFile + "|" + definesKey(defines);
  auto it = programs_.find(key);
  if (it == programs_.end()) it = programs_.emplace(key, library_.graphics(vertexFile, fragmentFile, defines)).first;
  return it->second;
}

}  // namespace pbr
