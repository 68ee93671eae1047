// Mirrors pbr::GpuLight (lighting/light_buffer.hpp), std430.
struct PointLight {
  vec4 positionRadius;  // world position, influence radius R
  vec4 colorIntensity;  // linear colour, luminous intensity I = P / (4 pi) in candela
};

layout(std430, binding = LIGHT_SSBO) readonly buffer LightBuffer {
  PointLight lights[];
};

// Mirrors pbr::LightingBlock (lighting/lighting_block.hpp).
layout(std140, binding = LIGHTING_UBO) uniform LightingBlock {
  vec4 ambient;  // uniform ambient radiance (PBR)
  uvec4 counts;  // x: lights in the frame
} lighting;

// Inverse-square falloff with a smooth window to zero at R (Karis 2013, "Real Shading in Unreal Engine 4"),
// limited to 1 so that a light on or inside a surface stays finite. R <= 0 means the light reaches nothing.
float distanceAttenuation(float d, float R) {
  if (!(R > 0.0)) return 0.0;
  float x = d / R;
  float x2 = x * x;
  float window = clamp(1.0 - x2 * x2, 0.0, 1.0);
  float dc = max(d, 0.01);
  return min(window * window / (dc * dc), 1.0);
}

// Unit direction to the light and its distance; a light exactly at the point shines along the normal.
vec3 directionToLight(vec3 position, vec3 normal, PointLight light, out float d) {
  vec3 toLight = light.positionRadius.xyz - position;
  d = length(toLight);
  return d > 1e-7 ? toLight / d : normal;
}
