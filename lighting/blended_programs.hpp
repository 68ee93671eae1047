#pragma once
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "core/gl/program_cache.hpp"
#include "core/scene/binding_table.hpp"

namespace pbr {

// The programs one pass draws the BLEND surfaces with (core/gl/blended_surfaces.hpp): its fragment shader behind the
// geometry pass's vertex shader, one program per material permutation, looked up once per pass rather than per draw.
class BlendedPrograms {
 public:
  // `defines` gives the rest of a program's defines (binding points included) from the geometry pass's points.
  BlendedPrograms(ProgramCache& programs, std::string fragmentShader,
                  std::function<ShaderDefines(const std::vector<BindingPoint>&)> defines)
      : programs_(programs), fragmentShader_(std::move(fragmentShader)), defines_(std::move(defines)) {}

  const Program& get(const std::string& vertexShader, const ShaderDefines& material,
                     const std::vector<BindingPoint>& bindings) {
    const Program*& p = made_[&material];
    if (!p) p = &programs_.graphics(vertexShader, fragmentShader_, concat(material, defines_(bindings)));
    return *p;
  }

 private:
  ProgramCache& programs_;
  std::string fragmentShader_;
  std::function<ShaderDefines(const std::vector<BindingPoint>&)> defines_;
  std::map<const ShaderDefines*, const Program*> made_;  // the geometry pass keeps one list per permutation
};

}  // namespace pbr
