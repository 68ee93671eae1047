// Mirrors pbr::ObjectBlock (gbuffer/object_block.hpp).
layout(std140, binding = OBJECT_UBO) uniform ObjectBlock {
  mat4 model;
  mat4 normalMatrix;
  vec4 baseColor;    // linear rgb factor, alpha factor
  vec4 material;     // roughness, metalness, normal scale, occlusion strength
  vec4 emissive;     // linear emitted radiance factor, alpha cutoff
  vec4 orientation;  // x: sign of det(model)
} object;
