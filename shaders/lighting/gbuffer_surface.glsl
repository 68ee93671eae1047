// The surface a pixel of the G-buffer holds.
#include "../common/octahedral.glsl"
#include "surface.glsl"

layout(binding = SURFACE_BASE_COLOR_UNIT) uniform sampler2D gBaseColor;  // SRGB8_ALPHA8, linear when fetched
layout(binding = SURFACE_NORMAL_UNIT) uniform sampler2D gNormal;         // RG16 octahedral
layout(binding = SURFACE_MATERIAL_UNIT) uniform sampler2D gMaterial;     // RGBA8 roughness, metalness, occlusion,
                                                                         // 1 unlit
layout(binding = SURFACE_DEPTH_UNIT) uniform sampler2D gDepth;           // 32F reversed-Z
#if MATERIAL_SPECULAR
layout(binding = SURFACE_SPECULAR_UNIT) uniform sampler2D gSpecular;     // RGBA16F dielectric F0 / 0.04, F90
#endif
#if MATERIAL_CLEARCOAT
layout(binding = SURFACE_CLEARCOAT_UNIT) uniform sampler2D gClearcoat;   // RGBA16 strength, roughness, oct normal
#endif
#if MATERIAL_SHEEN
layout(binding = SURFACE_SHEEN_UNIT) uniform sampler2D gSheen;           // SRGB8_ALPHA8 colour, roughness
#endif

// False where the pixel saw no geometry (depth still at the reversed-Z clear value 0).
bool readSurface(ivec2 p, out Surface s) {
  float depth = texelFetch(gDepth, p, 0).r;
  if (depth <= 0.0) return false;
  placeSurface(viewPositionAt(vec2(p), depth), octDecode(texelFetch(gNormal, p, 0).xy), s);
  s.baseColor = texelFetch(gBaseColor, p, 0).rgb;
  vec4 m = texelFetch(gMaterial, p, 0);
  s.roughness = m.x;
  s.metalness = m.y;
  s.occlusion = m.z;
#if UNLIT_MATERIALS
  s.unlit = m.w > 0.5;
#endif
#if MATERIAL_SPECULAR
  vec4 specular = texelFetch(gSpecular, p, 0);
  s.dielectric = vec4(0.04 * specular.rgb, specular.a);
#endif
#if MATERIAL_CLEARCOAT
  vec4 coat = texelFetch(gClearcoat, p, 0);
  s.clearcoat = coat.x;
  s.clearcoatRoughness = coat.y;
  s.clearcoatNormal = octDecode(coat.zw);
#endif
#if MATERIAL_SHEEN
  vec4 sheen = texelFetch(gSheen, p, 0);
  s.sheenColor = sheen.rgb;
  s.sheenRoughness = sheen.a;
#endif
  return true;
}
