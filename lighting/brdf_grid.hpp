#pragma once
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "core/gl/shader_library.hpp"
#include "core/scene/shading_model.hpp"

namespace pbr {

// The lighting pass's PBR BRDF f (brdf.glsl under the variant's defines) evaluated on the GPU over a grid of
// view angle x perceptual roughness, the light at the mirror direction of the view: column a is the view angle
// (a + 0.5) / angles x 90 degrees, row r the roughness (r + 0.5) / roughnesses, values row by row (rgb; w 0).
// Needs a current GL context.
std::vector<glm::vec4> evaluateBrdfGrid(const ShaderLibrary& shaders, const ShadingVariant& variant,
                                        const glm::vec3& baseColor, float metalness, int angles, int roughnesses);

}  // namespace pbr
