#include "../common/math.glsl"

// Perceptual roughness below this makes a^2 underflow the useful float range (Filament's limit).
const float MIN_ROUGHNESS = 0.045;

float alphaFromRoughness(float roughness) {
  float r = max(roughness, MIN_ROUGHNESS);
  return r * r;
}

vec3 f0FromMaterial(vec3 baseColor, float metalness) { return mix(vec3(0.04), baseColor, metalness); }

// GGX / Trowbridge-Reitz NDF (Walter et al. 2007, "Microfacet Models for Refraction through Rough Surfaces"),
// written with sin2 = 1 - NoH^2 passed in: near the peak NoH rounds to 1 in float and 1 - NoH^2 would lose its
// digits against a^2 (6e-6 at roughness 0.05), so callers take sin2 as |N x H|^2.
float D_GGX(float NoH, float sin2, float a) {
  float k = a / (sin2 + NoH * NoH * a * a);
  return k * k / PI;
}

// Height-correlated Smith visibility G2 / (4 NoL NoV) (Heitz 2014, "Understanding the Masking-Shadowing Function").
float V_SmithGGXCorrelated(float NoV, float NoL, float a) {
  float a2 = a * a;
  float lambdaV = NoL * sqrt((NoV - a2 * NoV) * NoV + a2);
  float lambdaL = NoV * sqrt((NoL - a2 * NoL) * NoL + a2);
  return 0.5 / (lambdaV + lambdaL);
}

// Hammon's linear approximation of the height-correlated form (Hammon 2017, "PBR Diffuse Lighting for GGX+Smith").
float V_SmithGGXCorrelatedFast(float NoV, float NoL, float a) {
  return 0.5 / mix(2.0 * NoL * NoV, NoL + NoV, a);
}

// Schlick 1994, "An Inexpensive BRDF Model for Physically-based Rendering".
vec3 F_Schlick(vec3 F0, float VoH) { return F0 + (1.0 - F0) * pow5(1.0 - VoH); }

// Schlick's term with (1 - c)^5 fitted by a spherical Gaussian (Karis 2013, "Real Shading in Unreal Engine 4").
vec3 F_SchlickSG(vec3 F0, float VoH) { return F0 + (1.0 - F0) * exp2((-5.55473 * VoH - 6.98316) * VoH); }

// Both with a grazing reflectance F90 other than 1 (glTF's KHR_materials_specular).
vec3 F_Schlick(vec3 F0, float F90, float VoH) { return F0 + (F90 - F0) * pow5(1.0 - VoH); }
vec3 F_SchlickSG(vec3 F0, float F90, float VoH) {
  return F0 + (F90 - F0) * exp2((-5.55473 * VoH - 6.98316) * VoH);
}

// Separable (uncorrelated) Smith G1(l) G1(v) / (4 NoL NoV) for GGX (Heitz 2014, "Understanding the
// Masking-Shadowing Function"), G1 = 2 NoX / (NoX + sqrt(a^2 + (1 - a^2) NoX^2)) with the 2s cancelled.
float V_SmithGGXSeparable(float NoV, float NoL, float a) {
  float a2 = a * a;
  float gv = NoV + sqrt((NoV - a2 * NoV) * NoV + a2);
  float gl = NoL + sqrt((NoL - a2 * NoL) * NoL + a2);
  return 1.0 / (gv * gl);
}

// Beckmann NDF with alpha = roughness^2 (Walter et al. 2007, "Microfacet Models for Refraction through Rough
// Surfaces"); sin2 as for D_GGX. cos^2 is floored so that NoH = 0 gives exp(-huge) / tiny = 0, not 0 / 0.
float D_Beckmann(float NoH, float sin2, float a) {
  float c2 = max(NoH * NoH, 1e-8);
  return exp(-sin2 / (c2 * a * a)) / (PI * a * a * c2 * c2);
}

// Exact unpolarised Fresnel reflectance of a dielectric of relative index eta (Cook & Torrance 1982, "A Reflectance
// Model for Computer Graphics"); total internal reflection cannot occur from outside (eta > 1) but is kept finite.
float F_Dielectric(float c, float eta) {
  float g2 = eta * eta - 1.0 + c * c;
  if (g2 < 0.0) return 1.0;
  float g = sqrt(g2);
  float a = (g - c) / (g + c);
  float b = (c * (g + c) - 1.0) / (c * (g - c) + 1.0);
  return 0.5 * a * a * (1.0 + b * b);
}

// Index of refraction from normal-incidence reflectance: F0 = ((eta - 1) / (eta + 1))^2 solved for eta.
float iorFromF0(float f0) {
  float s = sqrt(clamp(f0, 0.0, 0.999));
  return (1.0 + s) / (1.0 - s);
}

// Burley 2012, "Physically-Based Shading at Disney": the diffuse retro-reflection factor, without 1/pi.
float burleyDiffuse(float NoV, float NoL, float LoH, float roughness) {
  float f90 = 0.5 + 2.0 * roughness * LoH * LoH;
  return (1.0 + (f90 - 1.0) * pow5(1.0 - NoL)) * (1.0 + (f90 - 1.0) * pow5(1.0 - NoV));
}

// Permutations: each term is chosen by one define named for its form (lighting/shading_model.cpp holds the
// names, LightingPass::permutation sets them). Without them, as the IBL shaders include this file, a term is the
// renderer's standard form.
#if !defined(VISIBILITY_EXACT) && !defined(VISIBILITY_HAMMON) && !defined(VISIBILITY_SEPARABLE)
#define VISIBILITY_EXACT 1
#endif
#if !defined(NDF_GGX) && !defined(NDF_BECKMANN)
#define NDF_GGX 1
#endif
#if !defined(FRESNEL_SCHLICK) && !defined(FRESNEL_EXACT) && !defined(FRESNEL_SCHLICK_SG)
#define FRESNEL_SCHLICK 1
#endif
#if !defined(DIFFUSE_LAMBERT_1_F) && !defined(DIFFUSE_LAMBERT_1_F_VH) && !defined(DIFFUSE_LAMBERT) && !defined(DIFFUSE_BURLEY)
#define DIFFUSE_LAMBERT_1_F 1
#endif

float visibility(float NoV, float NoL, float a) {
#if defined(VISIBILITY_HAMMON)
  return V_SmithGGXCorrelatedFast(NoV, NoL, a);
#elif defined(VISIBILITY_SEPARABLE)
  return V_SmithGGXSeparable(NoV, NoL, a);
#elif defined(VISIBILITY_EXACT)
  return V_SmithGGXCorrelated(NoV, NoL, a);
#endif
}

float distribution(float NoH, float sin2, float a) {
#if defined(NDF_BECKMANN)
  return D_Beckmann(NoH, sin2, a);
#elif defined(NDF_GGX)
  return D_GGX(NoH, sin2, a);
#endif
}

// KHR_materials_ior and KHR_materials_specular: a scene whose materials set them shades with each surface's
// dielectric F0 colour and F90 (`dielectric`: rgb, a; glTF's fresnel_mix scales F0 to F90 where the core material's
// is 1). The core material's are 0.04 and 1, for which the forms below compute exactly what the core forms do.
// The lighting pass sets MATERIAL_SPECULAR (LightingOptions::specularMaterials); the other shaders leave it 0.

#if MATERIAL_SPECULAR
// The surface being shaded: set before its BRDF is evaluated (model_pbr.glsl's beginShading).
vec4 gDielectric = vec4(vec3(0.04), 1.0);

vec3 fresnel(vec3 baseColor, float metalness, vec4 dielectric, float c) {
#if defined(FRESNEL_EXACT)
  // Each channel's index of refraction from F0 / F90, the exact term scaled to F90.
  vec3 metal = F_Schlick(baseColor, c);
  vec3 f0 = dielectric.rgb / max(dielectric.a, 1e-6);
  vec3 exact =
      vec3(F_Dielectric(c, iorFromF0(f0.r)), F_Dielectric(c, iorFromF0(f0.g)), F_Dielectric(c, iorFromF0(f0.b)));
  return mix(dielectric.a * exact, metal, metalness);
#else
  vec3 F0 = mix(dielectric.rgb, baseColor, metalness);
  float F90 = dielectric.a + (1.0 - dielectric.a) * metalness;  // 1 exactly for the core material
#if defined(FRESNEL_SCHLICK_SG)
  return F_SchlickSG(F0, F90, c);
#else
  return F_Schlick(F0, F90, c);
#endif
#endif
}

// The Fresnel term the diffuse lobe's weight takes: glTF's fresnel_mix weights the base by 1 - max_value(F) of the
// dielectric, which every form here reaches at the largest channel of F0.
vec3 diffuseFresnel(vec3 baseColor, float metalness, vec4 dielectric, float c) {
  float largest = max(dielectric.r, max(dielectric.g, dielectric.b));
  return fresnel(baseColor, metalness, vec4(vec3(largest), dielectric.a), c);
}
#endif

// Metals take Schlick from their base colour; the dielectric part Schlick or the exact term with eta from 0.04,
// blended by metalness as F0 is. The spherical-Gaussian form replaces Schlick's power for the whole F0.
vec3 fresnel(vec3 baseColor, float metalness, float c) {
#if defined(FRESNEL_EXACT)
  vec3 metal = baseColor + (1.0 - baseColor) * pow5(1.0 - c);
  return mix(vec3(F_Dielectric(c, iorFromF0(0.04))), metal, metalness);
#elif defined(FRESNEL_SCHLICK_SG)
  return F_SchlickSG(f0FromMaterial(baseColor, metalness), c);
#elif defined(FRESNEL_SCHLICK)
  return F_Schlick(f0FromMaterial(baseColor, metalness), c);
#endif
}

#if MATERIAL_TRANSMISSION
// KHR_materials_transmission (a transmissive material's forward draw, lighting/forward.frag): the base that
// fresnel_mix weights is mix(diffuse, specular_btdf baseColor, transmission). The surface being shaded sets its
// transmission factor and the radiance seen through it (transmission.glsl) before its BRDF is evaluated.
float gTransmission = 0.0;
vec3 gBehind = vec3(0.0);
#endif

// The diffuse lobe f_d, weighted by (1 - metalness). The default weight (1 - F(n.v)) takes Fresnel at the view
// angle, the share of light the specular lobe can take at most. Weighting by (1 - F(v.h)) instead, as glTF's
// sample viewer does, gives a white dielectric a directional albedo up to 1.84 at grazing views (roughness 0.05,
// n.v 0.01; measured in tests/test_reference_brdf.cpp).
vec3 diffuseLobe(vec3 baseColor, float metalness, float roughness, float NoV, float NoL, float VoH) {
#if MATERIAL_SPECULAR && defined(DIFFUSE_LAMBERT_1_F_VH)
  vec3 weight = 1.0 - diffuseFresnel(baseColor, metalness, gDielectric, VoH);
#elif MATERIAL_SPECULAR && defined(DIFFUSE_LAMBERT_1_F)
  vec3 weight = 1.0 - diffuseFresnel(baseColor, metalness, gDielectric, NoV);
#elif defined(DIFFUSE_LAMBERT_1_F_VH)
  vec3 weight = 1.0 - fresnel(baseColor, metalness, VoH);
#elif defined(DIFFUSE_LAMBERT)
  vec3 weight = vec3(1.0);
#elif defined(DIFFUSE_BURLEY)
  vec3 weight = vec3(burleyDiffuse(NoV, NoL, VoH, max(roughness, MIN_ROUGHNESS)));
#elif defined(DIFFUSE_LAMBERT_1_F)
  vec3 weight = 1.0 - fresnel(baseColor, metalness, NoV);
#endif
#if MATERIAL_TRANSMISSION
  return weight * (1.0 - metalness) * (1.0 - gTransmission) * baseColor / PI;
#else
  return weight * (1.0 - metalness) * baseColor / PI;
#endif
}

// The terms of brdfCookTorrance that depend on the surface and the view only: a pixel computes them once for
// all its lights. `diffuse` is the whole diffuse lobe where no term of it depends on the light.
struct BrdfSurface {
  vec3 N, V, baseColor;
  float NoV, roughness, metalness, a;
#if defined(DIFFUSE_LAMBERT_1_F) || defined(DIFFUSE_LAMBERT)
  vec3 diffuse;
#endif
};

BrdfSurface brdfSurface(vec3 N, vec3 V, float NoV, vec3 baseColor, float roughness, float metalness) {
  BrdfSurface b;
  b.N = N;
  b.V = V;
  b.baseColor = baseColor;
  b.NoV = NoV;
  b.roughness = roughness;
  b.metalness = metalness;
  b.a = alphaFromRoughness(roughness);
#if defined(DIFFUSE_LAMBERT_1_F) || defined(DIFFUSE_LAMBERT)
  b.diffuse = diffuseLobe(baseColor, metalness, roughness, NoV, 0.0, 0.0);
#endif
  return b;
}

// Cook-Torrance specular plus the diffuse lobe for light from L; returns f_d + f_s.
vec3 brdfCookTorrance(BrdfSurface b, vec3 L) {
  vec3 H = normalize(b.V + L);
  vec3 NxH = cross(b.N, H);
  float NoL = max(dot(b.N, L), 0.0);
  float NoH = clamp(dot(b.N, H), 0.0, 1.0);
  float VoH = clamp(dot(b.V, H), 0.0, 1.0);
#if MATERIAL_SPECULAR
  vec3 F = fresnel(b.baseColor, b.metalness, gDielectric, VoH);
#else
  vec3 F = fresnel(b.baseColor, b.metalness, VoH);
#endif
  vec3 specular = distribution(NoH, dot(NxH, NxH), b.a) * visibility(b.NoV, NoL, b.a) * F;
#if defined(DIFFUSE_LAMBERT_1_F) || defined(DIFFUSE_LAMBERT)
  return b.diffuse + specular;
#else
  return diffuseLobe(b.baseColor, b.metalness, b.roughness, b.NoV, NoL, VoH) + specular;
#endif
}

vec3 brdfCookTorrance(vec3 N, vec3 V, vec3 L, float NoV, vec3 baseColor, float roughness, float metalness) {
  return brdfCookTorrance(brdfSurface(N, V, NoV, baseColor, roughness, metalness), L);
}
