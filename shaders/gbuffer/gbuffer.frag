#version 450 core
// The glTF metal-rough material into the G-buffer. Each *_MAP define (0 or 1) says whether the draw samples that
// texture, so untextured draws sample nothing, and each map is sampled through its own UV transform;
// ALPHA_MASK discards below the alpha cutoff.
#include "../common/octahedral.glsl"
#include "object.glsl"

layout(location = 0) in vec3 vNormal;
layout(location = 1) in vec2 vUv;
#if NORMAL_MAP
layout(location = 2) in vec4 vTangent;
#endif

#if BASE_COLOR_MAP
layout(binding = BASE_COLOR_MAP_UNIT) uniform sampler2D baseColorMap;  // SRGB8_ALPHA8
#endif
#if METALLIC_ROUGHNESS_MAP
layout(binding = METALLIC_ROUGHNESS_MAP_UNIT) uniform sampler2D metallicRoughnessMap;  // G roughness, B metalness
#endif
#if NORMAL_MAP
layout(binding = NORMAL_MAP_UNIT) uniform sampler2D normalMap;  // tangent space, +Y up the image
#endif
#if OCCLUSION_MAP
layout(binding = OCCLUSION_MAP_UNIT) uniform sampler2D occlusionMap;  // R
#endif
#if EMISSIVE_MAP
layout(binding = EMISSIVE_MAP_UNIT) uniform sampler2D emissiveMap;  // SRGB8_ALPHA8
#endif

// A map's texture coordinates after its KHR_texture_transform: (u, v, 1) times the rows of the affine map.
vec2 mapUv(int unit) { return vec3(vUv, 1.0) * object.uvTransform[unit]; }

layout(location = 0) out vec4 outBaseColor;  // SRGB8_ALPHA8: encoded on write
layout(location = 1) out vec2 outNormal;     // RG16 octahedral
layout(location = 2) out vec4 outMaterial;   // RGBA8 roughness, metalness, occlusion, unused
layout(location = 3) out vec4 outEmission;   // the frame's RGBA16F radiance target, which lighting adds to

void main() {
  vec4 base = object.baseColor;
#if BASE_COLOR_MAP
  base *= texture(baseColorMap, mapUv(BASE_COLOR_MAP_UNIT));
#endif
  float roughness = object.material.x;
  float metalness = object.material.y;
#if METALLIC_ROUGHNESS_MAP
  vec4 metallicRoughness = texture(metallicRoughnessMap, mapUv(METALLIC_ROUGHNESS_MAP_UNIT));
  roughness *= metallicRoughness.g;
  metalness *= metallicRoughness.b;
#endif
  vec3 n = normalize(vNormal);
#if NORMAL_MAP
  // glTF scales the tangent-space normal's xy by normalTexture.scale.
  vec3 encoded = texture(normalMap, mapUv(NORMAL_MAP_UNIT)).xyz;
  vec3 tangentNormal = normalize((encoded * 2.0 - 1.0) * vec3(object.material.zz, 1.0));
  // The frame stays the mesh's under a rotating UV transform, as in Blender, whose Normal Map node takes its
  // tangents from the UV map and not from a Mapping node's coordinates.
  // Gram-Schmidt: interpolation and non-uniform scaling leave the tangent off the surface.
  vec3 t = vTangent.xyz - n * dot(n, vTangent.xyz);
  if (dot(t, t) > 1e-12) {
    t = normalize(t);
    vec3 b = cross(n, t) * vTangent.w;
    n = normalize(mat3(t, b, n) * tangentNormal);
  }
#endif
  // Only double-sided draws show back faces; seen from behind, the surface faces the other way.
  if (!gl_FrontFacing) n = -n;
  float occlusion = 1.0;
#if OCCLUSION_MAP
  occlusion = 1.0 + object.material.w * (texture(occlusionMap, mapUv(OCCLUSION_MAP_UNIT)).r - 1.0);
#endif
  vec3 emitted = object.emissive.rgb;
#if EMISSIVE_MAP
  emitted *= texture(emissiveMap, mapUv(EMISSIVE_MAP_UNIT)).rgb;
#endif
#if ALPHA_MASK
  // After every texture() call: implicit derivatives are undefined once neighbours may have discarded.
  if (base.a < object.emissive.w) discard;
#endif
  outBaseColor = vec4(base.rgb, 1.0);
  outNormal = octEncode(n);
  outMaterial = vec4(roughness, metalness, occlusion, 0.0);
  outEmission = vec4(emitted, 0.0);
}
