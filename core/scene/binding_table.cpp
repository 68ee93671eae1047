#include "core/scene/binding_table.hpp"

#include <stdexcept>
#include <string>

namespace pbr {

ShaderDefines bindingDefines(std::initializer_list<BindingPoint> points) {
  return bindingDefines(std::vector<BindingPoint>(points));
}

ShaderDefines bindingDefines(const std::vector<BindingPoint>& points) {
  ShaderDefines defines;
  for (auto a = points.begin(); a != points.end(); ++a) {
    for (auto b = points.begin(); b != a; ++b) {
      if (std::string(a->define) == b->define) {
        throw std::logic_error(std::string("binding point ") + a->define + " is declared twice");
      }
      if (a->kind == b->kind && a->index == b->index) {
        throw std::logic_error(std::string("binding points ") + b->define + " and " + a->define + " share index " +
                               std::to_string(a->index));
      }
    }
    defines.push_back({a->define, std::to_string(a->index), true});
  }
  return defines;
}

ShaderDefines concat(ShaderDefines defines, const ShaderDefines& more) {
  defines.insert(defines.end(), more.begin(), more.end());
  return defines;
}

}  // namespace pbr
