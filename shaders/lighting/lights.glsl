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
// limited to 1 so that a light on or inside a surface stays finite. R <= 0 means the light reaches nothing. Takes
// the squared distance d2: the window and the falloff need no square root.
float distanceAttenuation(float d2, float R) {
  float x2 = d2 / (R * R);
  float window = clamp(1.0 - x2 * x2, 0.0, 1.0);
  float attenuation = min(window * window / max(d2, 1e-4), 1.0);
  return R > 0.0 ? attenuation : 0.0;
}

// Unit direction to the light and its squared distance; a light exactly at the point shines along the normal.
vec3 directionToLight(vec3 position, vec3 normal, PointLight light, out float d2) {
  vec3 toLight = light.positionRadius.xyz - position;
  d2 = dot(toLight, toLight);
  return d2 > 1e-14 ? toLight * inversesqrt(d2) : normal;
}
