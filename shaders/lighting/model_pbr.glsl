// The PBR shading model: Cook-Torrance GGX, photometric point lights, HDR output.
#include "brdf.glsl"

#if MATERIAL_SHEEN
#include "sheen.glsl"
// KHR_materials_sheen: the fibre lobe sheenColor D V over the base, whose lobes and ambient and environment light
// are scaled by 1 - max(sheenColor) E(n.v), the albedo scaling in the form that depends on the view alone (the
// extension allows it for direct and indirect light alike). E is tabulated (lighting/sheen_albedo.comp).
layout(binding = SHEEN_ALBEDO_UNIT) uniform sampler2D sheenAlbedo;
float gSheenE, gSheenScale, gSheenR;

float sheenAlbedoAt(float NoV, float roughness) {
  vec2 size = vec2(textureSize(sheenAlbedo, 0));
  vec2 uv = tableUv(vec2(NoV, roughness), size);
  return textureLod(sheenAlbedo, uv, 0.0).r;
}

// The sheen's D V n.l for light from L (0 below the horizon).
float sheenLobe(Surface s, vec3 L) {
  float NoL = dot(s.normal, L);
  if (NoL <= 0.0) return 0.0;
  vec3 H = normalize(s.V + L);
  vec3 NxH = cross(s.normal, H);
  return D_Charlie(dot(NxH, NxH), gSheenR) * V_Charlie(s.NoV, NoL, gSheenR) * NoL;
}
#endif

#if MATERIAL_CLEARCOAT
// KHR_materials_clearcoat's fresnel_coat: a GGX layer of F0 0.04 on the coat's normal, weighted by clearcoat Fc,
// over everything else (the base's lobes, its ambient and environment light, its emission), weighted by
// 1 - clearcoat Fc; Fc is Schlick's at the coat's n.v, as the specification's implementation takes it. The coat's
// lobe is the variant's D and V with no Fresnel of its own.
float gCoatNoV, gCoatWeight, gCoatA;

float coatTransmission(Surface s) { return 1.0 - gCoatWeight; }

// The coat's D V n.l for light from L (0 below its horizon).
float coatLobe(Surface s, vec3 L) {
  float NoL = dot(s.clearcoatNormal, L);
  if (NoL <= 0.0) return 0.0;
  vec3 H = normalize(s.V + L);
  vec3 NxH = cross(s.clearcoatNormal, H);
  float NoH = clamp(dot(s.clearcoatNormal, H), 0.0, 1.0);
  return distribution(NoH, dot(NxH, NxH), gCoatA) * visibility(gCoatNoV, NoL, gCoatA) * NoL;
}
#endif

#if !IBL
// The variant's own directional albedo (lighting/ambient_albedo.comp): x, y the specular lobe for metals as
// F0 A + B, z for the dielectric, w the diffuse weight's mean; texel centres on the range ends.
layout(binding = AMBIENT_ALBEDO_UNIT) uniform sampler2D ambientAlbedo;

// Uniform ambient radiance times the directional albedo of the whole BRDF, f n.l integrated over the hemisphere.
vec3 shadeAmbient(Surface s) {
  vec2 size = vec2(textureSize(ambientAlbedo, 0));
  vec2 uv = tableUv(vec2(s.NoV, s.roughness), size);
  vec4 t = textureLod(ambientAlbedo, uv, 0.0);
#if MATERIAL_SPECULAR
  // The dielectric's albedo moved from the core material's by the split F0 A + F90 B (exact for Schlick's form).
  vec3 dielectric = t.z + (s.dielectric.rgb - 0.04) * t.x + (s.dielectric.a - 1.0) * t.y;
  vec3 specular = (1.0 - s.metalness) * dielectric + s.metalness * (s.baseColor * t.x + t.y);
#else
  vec3 specular = (1.0 - s.metalness) * t.z + s.metalness * (s.baseColor * t.x + t.y);
#endif
#if MATERIAL_SPECULAR && defined(DIFFUSE_LAMBERT_1_F)
  vec3 weight = 1.0 - diffuseFresnel(s.baseColor, s.metalness, s.dielectric, s.NoV);
#elif defined(DIFFUSE_LAMBERT_1_F)
  vec3 weight = 1.0 - fresnel(s.baseColor, s.metalness, s.NoV);  // constant over the hemisphere: exact
#elif defined(DIFFUSE_LAMBERT)
  vec3 weight = vec3(1.0);
#else
  vec3 weight = vec3(t.w);  // a dielectric's: exact for metalness 0 and 1, interpolated between
#endif
#if MATERIAL_TRANSMISSION
  // KHR_materials_transmission: the base's share gTransmission shows what lies behind instead of diffusing.
  vec3 base = weight * (1.0 - s.metalness) * s.baseColor;
  vec3 albedo = base * (1.0 - gTransmission) + specular;
  vec3 through = base * gTransmission * gBehind;
#else
  vec3 albedo = weight * (1.0 - s.metalness) * s.baseColor + specular;
#endif
#if MATERIAL_SHEEN
  if (s.sheenColor != vec3(0.0)) albedo = gSheenScale * albedo + s.sheenColor * gSheenE;
#endif
#if MATERIAL_SHEEN && MATERIAL_TRANSMISSION
  if (s.sheenColor != vec3(0.0)) through *= gSheenScale;
#endif
#if MATERIAL_CLEARCOAT
  // The coat's albedo is its lobe's with F 1: the metals' table at F0 1, A + B.
  vec2 coatUv = tableUv(vec2(gCoatNoV, s.clearcoatRoughness), size);
  vec4 coat = textureLod(ambientAlbedo, coatUv, 0.0);
  albedo = (1.0 - gCoatWeight) * albedo + gCoatWeight * (coat.x + coat.y);
#endif
#if MATERIAL_CLEARCOAT && MATERIAL_TRANSMISSION
  through *= 1.0 - gCoatWeight;
#endif
#if MATERIAL_TRANSMISSION
  return (lighting.ambient.rgb * albedo + through) * s.occlusion;
#else
  return lighting.ambient.rgb * albedo * s.occlusion;
#endif
}
#endif

// The pixel's BRDF terms that no light changes: computed once before the light loop, not per pair.
BrdfSurface gBrdf;

void beginShading(Surface s) {
#if MATERIAL_SPECULAR
  gDielectric = s.dielectric;
#endif
  gBrdf = brdfSurface(s.normal, s.V, s.NoV, s.baseColor, s.roughness, s.metalness);
#if MATERIAL_SHEEN
  gSheenR = sheenAlpha(s.sheenRoughness);
  gSheenE = sheenAlbedoAt(s.NoV, s.sheenRoughness);
  gSheenScale = 1.0 - max(s.sheenColor.r, max(s.sheenColor.g, s.sheenColor.b)) * gSheenE;
#endif
#if MATERIAL_CLEARCOAT
  gCoatNoV = max(dot(s.clearcoatNormal, s.V), 1e-4);
  gCoatWeight = s.clearcoat * (0.04 + 0.96 * pow5(1.0 - gCoatNoV));
  gCoatA = alphaFromRoughness(s.clearcoatRoughness);
#endif
}

#if MATERIAL_TRANSMISSION
// KHR_materials_transmission's specular_btdf for light from behind the surface, times |n.l|: the specification's
// thin-walled microfacet BTDF, GGX D and visibility about the transmission half vector H_T = normalize(V + L'),
// L' the light's direction mirrored through the surface's plane, weighted as the base of fresnel_mix is
// (1 - F of the dielectric, its largest channel) and tinted by the base colour.
vec3 transmissionLobe(Surface s, vec3 L) {
  float NoL = -dot(s.normal, L);
  vec3 mirrored = L + 2.0 * NoL * s.normal;
  vec3 H = normalize(s.V + mirrored);
  vec3 NxH = cross(s.normal, H);
  float NoH = clamp(dot(s.normal, H), 0.0, 1.0);
  float VoH = clamp(dot(s.V, H), 0.0, 1.0);
#if MATERIAL_SPECULAR
  vec3 F = diffuseFresnel(s.baseColor, 0.0, gDielectric, VoH);
#else
  vec3 F = fresnel(s.baseColor, 0.0, VoH);
#endif
  float lobe = distribution(NoH, dot(NxH, NxH), gBrdf.a) * visibility(s.NoV, NoL, gBrdf.a) * NoL;
  return (1.0 - F) * (gTransmission * (1.0 - s.metalness) * lobe) * s.baseColor;
}
#endif

// Light of colour `color` arriving from unit direction L with `strength` lux on a surface facing it: f E n.l.
vec3 shadeIncident(Surface s, vec3 L, vec3 color, float strength) {
#if MATERIAL_CLEARCOAT || MATERIAL_SHEEN
  // The coat may face a light the base turns from, and the other way round; without a sheen or a coat, the core's
  // sums.
  if (strength <= 0.0) return vec3(0.0);
  float NoL = dot(s.normal, L);
  vec3 radiance = NoL > 0.0 ? brdfCookTorrance(gBrdf, L) * color * (strength * NoL) : vec3(0.0);
#if MATERIAL_TRANSMISSION
  if (NoL < 0.0 && gTransmission > 0.0) radiance = transmissionLobe(s, L) * color * strength;
#endif
#if MATERIAL_SHEEN
  if (s.sheenColor != vec3(0.0)) {
    radiance = gSheenScale * radiance + s.sheenColor * sheenLobe(s, L) * color * strength;
  }
#endif
#if MATERIAL_CLEARCOAT
  if (s.clearcoat > 0.0) radiance = (1.0 - gCoatWeight) * radiance + gCoatWeight * coatLobe(s, L) * color * strength;
#endif
  return radiance;
#else
  float NoL = dot(s.normal, L);
#if MATERIAL_TRANSMISSION
  if (NoL < 0.0 && strength > 0.0 && gTransmission > 0.0) return transmissionLobe(s, L) * color * strength;
#endif
  if (NoL <= 0.0 || strength <= 0.0) return vec3(0.0);
  vec3 f = brdfCookTorrance(gBrdf, L);
  return f * color * (strength * NoL);
#endif
}

// A point light of intensity I gives I att / d^2 lux, att windowed and masked by a spot light's cone
// (lightAttenuation holds the 1 / d^2).
vec3 shadeLight(Surface s, PointLight light, vec4 cone) {
  float d2;
  vec3 L = directionToLight(s.position, s.normal, light, d2);
  float att = lightAttenuation(d2, L, light, cone);
  return shadeIncident(s, L, light.colorIntensity.rgb, light.colorIntensity.w * att);
}

vec3 shadeDirectional(Surface s, DirectionalLight light) {
  return shadeIncident(s, light.toLight.xyz, light.colorIlluminance.rgb, light.colorIlluminance.w);
}

vec3 finishShading(vec3 color) { return min(color, vec3(FP16_MAX)); }
