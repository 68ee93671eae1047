#version 450 core
// The lighting pass's BRDF (brdf.glsl under the variant's defines) on a grid of view angle x perceptual
// roughness, light at the mirror direction of the view (lighting/brdf_grid.hpp): the data of `pbr accuracy --slices`.
layout(local_size_x = 8, local_size_y = 8) in;

#include "../lighting/brdf.glsl"

layout(location = 0) uniform uvec2 gridSize;  // x: view angles over [0, 90) degrees, y: roughness over (0, 1)
layout(location = 1) uniform vec4 material;   // base colour, metalness
layout(std430, binding = BRDF_GRID_SSBO) writeonly buffer Values { vec4 values[]; };

void main() {
  uvec2 c = gl_GlobalInvocationID.xy;
  if (any(greaterThanEqual(c, gridSize))) return;
  float theta = (float(c.x) + 0.5) / float(gridSize.x) * 0.5 * PI;
  float roughness = (float(c.y) + 0.5) / float(gridSize.y);
  vec3 N = vec3(0.0, 0.0, 1.0);
  vec3 V = vec3(sin(theta), 0.0, cos(theta));
  vec3 L = vec3(-V.x, 0.0, V.z);
  float NoV = max(dot(N, V), 1e-4);  // as readSurface clamps it
  values[c.y * gridSize.x + c.x] = vec4(brdfCookTorrance(N, V, L, NoV, material.rgb, roughness, material.w), 0.0);
}
