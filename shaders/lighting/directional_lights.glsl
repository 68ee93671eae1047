// Mirrors pbr::DirectionalLightBlock (lighting/light_buffer.hpp), std140. No culling: every pixel shades all of
// them, before its point lights.
struct DirectionalLight {
  vec4 toLight;           // unit direction towards the light (against the way it travels)
  vec4 colorIlluminance;  // linear colour, illuminance E in lux
};

// The first DIRECTIONAL_LIGHTS are in use.
layout(std140, binding = DIRECTIONAL_LIGHT_UBO) uniform DirectionalLightBlock {
  DirectionalLight directionalLights[MAX_DIRECTIONAL_LIGHTS];
};
