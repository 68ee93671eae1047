#pragma once
#include <string>
#include <vector>

#include <glm/vec4.hpp>

#include "core/gl/gl_objects.hpp"
#include "core/gl/shader_library.hpp"

namespace pbr::test {

// Evaluates GLSL on the GPU, one compute invocation per input element, so that tests exercise the shipped
// shader functions with the driver's own float arithmetic rather than a C++ transcription of them.
//
// `source` follows `#version 450`: it may `#include` files under shaders/ (e.g. "lighting/brdf.glsl") and must
// define `vec4 probe(vec4 v)`, which maps input[i] to output[i]. Compile errors throw pbr::ShaderError naming
// `name`, where line n + 1 is line n of `source` (line 1 is the #version line the probe adds).
class GlslProbe {
 public:
  // Input and output live in std430 SSBOs at these bindings, within the 8 that every GL 4.3+ implementation
  // offers. Probes are compiled with the lighting module's binding defines (lighting/lighting_bindings.hpp), so
  // that they may include its GLSL and the IBL's; none of those files declares a storage block at 6 or 7.
  static constexpr unsigned kInputBinding = 6;
  static constexpr unsigned kOutputBinding = 7;

  GlslProbe(const std::string& name, const std::string& source, const ShaderDefines& defines = {});

  std::vector<glm::vec4> run(const std::vector<glm::vec4>& input) const;

 private:
  Program program_;
};

}  // namespace pbr::test
