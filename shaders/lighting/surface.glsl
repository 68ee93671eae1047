#include "../common/frame.glsl"
#include "../common/octahedral.glsl"

layout(binding = SURFACE_BASE_COLOR_UNIT) uniform sampler2D gBaseColor;  // SRGB8_ALPHA8, linear when fetched
layout(binding = SURFACE_NORMAL_UNIT) uniform sampler2D gNormal;         // RG16 octahedral
layout(binding = SURFACE_MATERIAL_UNIT) uniform sampler2D gMaterial;     // RGBA8 roughness, metalness, occlusion
layout(binding = SURFACE_DEPTH_UNIT) uniform sampler2D gDepth;           // 32F reversed-Z

struct Surface {
  vec3 position;      // world
  float viewDepth;    // distance along the view axis (-z in view space)
  vec3 normal;
  float NoV;          // clamped away from 0 so that grazing pixels stay finite
  vec3 V;             // unit vector to the camera
  float roughness;    // perceptual
  vec3 baseColor;
  float metalness;
  float occlusion;    // of the ambient term only: point lights are direct light
};

// False where the pixel saw no geometry (depth still at the reversed-Z clear value 0).
bool readSurface(ivec2 p, out Surface s) {
  float depth = texelFetch(gDepth, p, 0).r;
  if (depth <= 0.0) return false;
  vec2 ndc = (vec2(p) + 0.5) * frame.viewport.zw * 2.0 - 1.0;
  // Reversed-Z projection: depth = -P22 - P32 / z_view, solved for z_view; exact where the inverse
  // view-projection matrix would lose digits.
  float zView = -frame.projParams.w / (depth + frame.projParams.z);
  vec3 viewPos = vec3(-zView * ndc.x / frame.projParams.x, -zView * ndc.y / frame.projParams.y, zView);
  s.position = (frame.inverseView * vec4(viewPos, 1.0)).xyz;
  s.viewDepth = -zView;
  s.normal = octDecode(texelFetch(gNormal, p, 0).xy);
  s.V = normalize(frame.cameraPosition.xyz - s.position);
  s.NoV = max(dot(s.normal, s.V), 1e-4);
  s.baseColor = texelFetch(gBaseColor, p, 0).rgb;
  vec3 m = texelFetch(gMaterial, p, 0).xyz;
  s.roughness = m.x;
  s.metalness = m.y;
  s.occlusion = m.z;
  return true;
}
