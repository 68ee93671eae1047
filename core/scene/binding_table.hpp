#pragma once
#include <initializer_list>
#include <vector>

#include "core/scene/shader_sources.hpp"

namespace pbr {

// The binding spaces of GL: a uniform buffer, a storage buffer, a texture unit and an image unit may share an index.
enum class BindingKind { UniformBuffer, StorageBuffer, TextureUnit, ImageUnit };

// One binding point, named once for both languages: C++ binds at `index`, GLSL reads the `define` its program is
// compiled with (`layout(binding = FRAME_UBO)`). Each module declares the points it owns next to what it binds.
struct BindingPoint {
  const char* define;
  BindingKind kind;
  unsigned index;
};

// "#define NAME index" for each point of the tables a program's sources read. Throws std::logic_error when two
// points share a name, or a kind and an index: tables bound together must not overlap.
ShaderDefines bindingDefines(std::initializer_list<BindingPoint> points);
ShaderDefines bindingDefines(const std::vector<BindingPoint>& points);

// `defines` followed by `more`.
ShaderDefines concat(ShaderDefines defines, const ShaderDefines& more);

}  // namespace pbr
