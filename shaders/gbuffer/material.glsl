// The glTF metal-rough material at a fragment, shared by the G-buffer pass and the forward lighting of BLEND
// materials (shaders/lighting/forward.frag). Each *_MAP define (0 or 1) says whether the draw samples that texture,
// so untextured draws sample nothing, and each map is sampled through its own UV transform.
#include "object.glsl"

layout(location = 0) in vec3 vNormal;
layout(location = 1) in vec2 vUv;
#if NORMAL_MAP || CLEARCOAT_NORMAL_MAP
layout(location = 2) in vec4 vTangent;
#endif
#if UV1
layout(location = 3) in vec2 vUv1;
#endif
#if VERTEX_COLORS
layout(location = 4) in vec4 vColor;
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
// The material extensions' maps, each named only in the permutations of materials that have it.
#if CLEARCOAT_MAP
layout(binding = CLEARCOAT_MAP_UNIT) uniform sampler2D clearcoatMap;  // R: the coat's strength
#endif
#if CLEARCOAT_ROUGHNESS_MAP
layout(binding = CLEARCOAT_ROUGHNESS_MAP_UNIT) uniform sampler2D clearcoatRoughnessMap;  // G
#endif
#if CLEARCOAT_NORMAL_MAP
layout(binding = CLEARCOAT_NORMAL_MAP_UNIT) uniform sampler2D clearcoatNormalMap;  // tangent space, +Y up the image
#endif
#if SHEEN_COLOR_MAP
layout(binding = SHEEN_COLOR_MAP_UNIT) uniform sampler2D sheenColorMap;  // SRGB8_ALPHA8
#endif
#if SHEEN_ROUGHNESS_MAP
layout(binding = SHEEN_ROUGHNESS_MAP_UNIT) uniform sampler2D sheenRoughnessMap;  // A
#endif
#if SPECULAR_MAP
layout(binding = SPECULAR_MAP_UNIT) uniform sampler2D specularMap;  // A: the specular strength
#endif
#if SPECULAR_COLOR_MAP
layout(binding = SPECULAR_COLOR_MAP_UNIT) uniform sampler2D specularColorMap;  // SRGB8_ALPHA8
#endif
#if TRANSMISSION_MAP
layout(binding = TRANSMISSION_MAP_UNIT) uniform sampler2D transmissionMap;  // R
#endif
#if THICKNESS_MAP
layout(binding = THICKNESS_MAP_UNIT) uniform sampler2D thicknessMap;  // G
#endif

// A map's texture coordinates after its KHR_texture_transform: (u, v, 1) times the rows of the affine map. With
// UV1, the maps whose bit is set in object.orientation.y read the second UV set.
vec2 mapUv(int unit) {
#if UV1
  vec2 uv = ((uint(object.orientation.y) >> uint(unit)) & 1u) != 0u ? vUv1 : vUv;
#else
  vec2 uv = vUv;
#endif
  return vec3(uv, 1.0) * object.uvTransform[unit];
}

// An extension map's texture coordinates, `i` its place in extensionMaps' order (core/scene/scene.hpp).
vec2 extensionUv(int i) {
#if UV1
  vec2 uv = ((uint(object.orientation.z) >> uint(i)) & 1u) != 0u ? vUv1 : vUv;
#else
  vec2 uv = vUv;
#endif
  return vec3(uv, 1.0) * object.extensionUvTransform[i];
}

// A tangent-space normal `encoded` from a map, its xy scaled by `scale`, on the surface of unit normal n (glTF's
// normalTexture and clearcoatNormalTexture alike). Gram-Schmidt: interpolation and non-uniform scaling leave the
// tangent off the surface.
#if NORMAL_MAP || CLEARCOAT_NORMAL_MAP
vec3 mappedNormal(vec3 n, vec3 encoded, float scale) {
  vec3 tangentNormal = normalize((encoded * 2.0 - 1.0) * vec3(scale, scale, 1.0));
  vec3 t = vTangent.xyz - n * dot(n, vTangent.xyz);
  if (dot(t, t) <= 1e-12) return n;
  t = normalize(t);
  vec3 b = cross(n, t) * vTangent.w;
  return normalize(mat3(t, b, n) * tangentNormal);
}
#endif

struct MaterialSample {
  vec4 base;        // linear base colour and alpha
  vec3 normal;      // unit, facing the viewer's side of a double-sided surface
  float roughness;  // perceptual
  float metalness;
  float occlusion;  // of ambient light
  vec3 emitted;     // radiance
  vec4 dielectric;  // F0 colour and F90 of the dielectric part (KHR_materials_ior, KHR_materials_specular)
  // KHR_materials_clearcoat: strength, perceptual roughness and the coat's normal, the interpolated one (no map)
  float clearcoat;
  float clearcoatRoughness;
  vec3 clearcoatNormal;
  vec3 sheenColor;  // KHR_materials_sheen: the fibre lobe's colour (black: none) and roughness
  float sheenRoughness;
#if MATERIAL_TRANSMISSION
  float transmission;  // KHR_materials_transmission's factor
  float thickness;     // KHR_materials_volume's, in the object's space (0: thin-walled)
#endif
};

MaterialSample sampleMaterial() {
  MaterialSample m;
  m.base = object.baseColor;
#if VERTEX_COLORS
  m.base *= vColor;  // glTF: COLOR_0 multiplies the base colour and its alpha
#endif
#if BASE_COLOR_MAP
  m.base *= texture(baseColorMap, mapUv(BASE_COLOR_MAP_UNIT));
#endif
  m.roughness = object.material.x;
  m.metalness = object.material.y;
#if METALLIC_ROUGHNESS_MAP
  vec4 metallicRoughness = texture(metallicRoughnessMap, mapUv(METALLIC_ROUGHNESS_MAP_UNIT));
  m.roughness *= metallicRoughness.g;
  m.metalness *= metallicRoughness.b;
#endif
  vec3 n = normalize(vNormal);
#if NORMAL_MAP
  // glTF scales the tangent-space normal's xy by normalTexture.scale. The frame stays the mesh's under a rotating
  // UV transform, as in Blender, whose Normal Map node takes its tangents from the UV map and not from a Mapping
  // node's coordinates.
  n = mappedNormal(n, texture(normalMap, mapUv(NORMAL_MAP_UNIT)).xyz, object.material.z);
#endif
  // Only double-sided draws show back faces; seen from behind, the surface faces the other way.
  if (!gl_FrontFacing) n = -n;
  m.normal = n;
  m.clearcoatNormal = normalize(vNormal);
#if CLEARCOAT_NORMAL_MAP
  m.clearcoatNormal = mappedNormal(m.clearcoatNormal, texture(clearcoatNormalMap, extensionUv(2)).xyz, object.layers.w);
#endif
  if (!gl_FrontFacing) m.clearcoatNormal = -m.clearcoatNormal;
  m.occlusion = 1.0;
#if OCCLUSION_MAP
  m.occlusion = 1.0 + object.material.w * (texture(occlusionMap, mapUv(OCCLUSION_MAP_UNIT)).r - 1.0);
#endif
  m.emitted = object.emissive.rgb;
#if EMISSIVE_MAP
  m.emitted *= texture(emissiveMap, mapUv(EMISSIVE_MAP_UNIT)).rgb;
#endif
  m.dielectric = object.dielectric;
#if SPECULAR_MAP || SPECULAR_COLOR_MAP
  // KHR_materials_specular's maps multiply its factors before F0 is clamped: min(f0 specularColor, 1) specular.
  float strength = object.dielectric.a;
  vec3 color = object.specularFactors.rgb;
#if SPECULAR_MAP
  strength *= texture(specularMap, extensionUv(5)).a;
#endif
#if SPECULAR_COLOR_MAP
  color *= texture(specularColorMap, extensionUv(6)).rgb;
#endif
  m.dielectric = vec4(min(object.specularFactors.w * color, vec3(1.0)) * strength, strength);
#endif
  m.clearcoat = object.layers.x;
#if CLEARCOAT_MAP
  m.clearcoat *= texture(clearcoatMap, extensionUv(0)).r;
#endif
  m.clearcoatRoughness = object.layers.y;
#if CLEARCOAT_ROUGHNESS_MAP
  m.clearcoatRoughness *= texture(clearcoatRoughnessMap, extensionUv(1)).g;
#endif
  m.sheenColor = object.sheenColor.rgb;
#if SHEEN_COLOR_MAP
  m.sheenColor *= texture(sheenColorMap, extensionUv(3)).rgb;
#endif
  m.sheenRoughness = object.layers.z;
#if SHEEN_ROUGHNESS_MAP
  m.sheenRoughness *= texture(sheenRoughnessMap, extensionUv(4)).a;
#endif
#if MATERIAL_TRANSMISSION
  m.transmission = object.transmission.x;
#if TRANSMISSION_MAP
  m.transmission *= texture(transmissionMap, extensionUv(7)).r;
#endif
  m.thickness = object.transmission.y;
#if THICKNESS_MAP
  m.thickness *= texture(thicknessMap, extensionUv(8)).g;
#endif
#endif
  return m;
}
