#include "../common/bindings.glsl"

// Mirrors pbr::ObjectBlock (gbuffer/object_block.hpp).
layout(std140, binding = OBJECT_UBO) uniform ObjectBlock {
  mat4 model;
  mat4 normalMatrix;
  vec4 baseColor;  // linear rgb, a unused
  vec4 material;   // roughness, metalness
} object;
