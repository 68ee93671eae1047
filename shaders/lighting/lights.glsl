// Mirrors pbr::GpuLight (lighting/light_buffer.hpp), std430.
struct PointLight {
  vec4 positionRadius;  // world position, influence radius R
  vec4 colorIntensity;  // linear colour, luminous intensity I = P / (4 pi) in candela
};

layout(std430, binding = LIGHT_SSBO) readonly buffer LightBuffer {
  PointLight lights[];
};

#if SPOT_LIGHTS
// Mirrors pbr::GpuSpotCone, one per light, indexed as `lights`: the axis times the falloff's scale, and its offset.
// A point light's, (0, 0, 0, 1), leaves it unmasked.
layout(std430, binding = SPOT_CONE_SSBO) readonly buffer SpotConeBuffer {
  vec4 spotCones[];
};
#endif

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

// A spot light's smooth angular falloff (KHR_lights_punctual): clamp(cos(angle to the axis) s + o, 0, 1)^2, with
// the axis premultiplied by s; L points from the surface to the light.
float spotAttenuation(vec4 cone, vec3 L) {
  float x = clamp(dot(cone.xyz, -L) + cone.w, 0.0, 1.0);
  return x * x;
}

// The light's distance window times, with spot lights in the frame, its cone's falloff.
float lightAttenuation(float d2, vec3 L, PointLight light, vec4 cone) {
#if SPOT_LIGHTS
  return distanceAttenuation(d2, light.positionRadius.w) * spotAttenuation(cone, L);
#else
  return distanceAttenuation(d2, light.positionRadius.w);
#endif
}

// Unit direction to the light and its squared distance; a light exactly at the point shines along the normal.
vec3 directionToLight(vec3 position, vec3 normal, PointLight light, out float d2) {
  vec3 toLight = light.positionRadius.xyz - position;
  d2 = dot(toLight, toLight);
  return d2 > 1e-14 ? toLight * inversesqrt(d2) : normal;
}
