// Mirrors pbr::DirectionalLightBlock (lighting/light_buffer.hpp), std140. No culling: every pixel shades all of
// them, before its point lights.
struct DirectionalLight {
  vec4 toLight;           // unit direction towards the light (against the way it travels)
  vec4 colorIlluminance;  // linear colour, illuminance E in lux
};

layout(std140, binding = DIRECTIONAL_LIGHT_UBO) uniform DirectionalLightBlock {
  uvec4 directionalCount;  // x: lights in use
  DirectionalLight directionalLights[MAX_DIRECTIONAL_LIGHTS];
};
