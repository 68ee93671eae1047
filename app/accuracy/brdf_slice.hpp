#pragma once
#include <vector>

#include <glm/vec3.hpp>

#include "core/gl/shader_library.hpp"
#include "core/scene/shading_model.hpp"

namespace pbr {

// Relative error of a PBR variant's GLSL BRDF against the reference BRDF (reference/reference_brdf.hpp) over
// (angle between n and v) x (perceptual roughness), with the light fixed at the mirror direction of the view,
// where the specular lobe peaks and visibility and Fresnel matter most. There H = N, where GGX and Beckmann both
// peak at 1 / (pi a^2): a slice shows visibility, Fresnel and diffuse errors, not the NDF's shape (the frames of
// `pbr accuracy` do). Error: |sum_rgb f - sum_rgb f_ref| / sum_rgb f_ref.
struct BrdfSlice {
  int angles = 0;       // columns: view angle (a + 0.5) / angles x 90 degrees
  int roughnesses = 0;  // rows: perceptual roughness (r + 0.5) / roughnesses, smallest at the top
  std::vector<float> relativeError;
  float at(int a, int r) const { return relativeError[size_t(r) * angles + a]; }
};

struct SliceMaterial {
  glm::vec3 baseColor{0.8f};
  float metalness = 0.0f;
};

// Needs a current GL context.
BrdfSlice computeBrdfSlice(const ShaderLibrary& shaders, const ShadingVariant& variant, const SliceMaterial& material,
                           int angles, int roughnesses);

}  // namespace pbr
