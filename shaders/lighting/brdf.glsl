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

// Permutations (LightingPass::program): VISIBILITY 0 exact height-correlated, 1 Hammon, 2 separable Smith;
// NDF 0 GGX, 1 Beckmann; FRESNEL 0 Schlick, 1 exact for the dielectric part; DIFFUSE 0 Lambert (1 - F(n.v)),
// 1 plain Lambert, 2 Burley.
#ifndef VISIBILITY
#define VISIBILITY 0
#endif
#ifndef NDF
#define NDF 0
#endif
#ifndef FRESNEL
#define FRESNEL 0
#endif
#ifndef DIFFUSE
#define DIFFUSE 0
#endif

float visibility(float NoV, float NoL, float a) {
#if VISIBILITY == 1
  return V_SmithGGXCorrelatedFast(NoV, NoL, a);
#elif VISIBILITY == 2
  return V_SmithGGXSeparable(NoV, NoL, a);
#else
  return V_SmithGGXCorrelated(NoV, NoL, a);
#endif
}

float distribution(float NoH, float sin2, float a) {
#if NDF == 1
  return D_Beckmann(NoH, sin2, a);
#else
  return D_GGX(NoH, sin2, a);
#endif
}

// Metals take Schlick from their base colour; the dielectric part Schlick or the exact term with eta from 0.04,
// blended by metalness as F0 is.
vec3 fresnel(vec3 baseColor, float metalness, float c) {
#if FRESNEL == 1
  vec3 metal = baseColor + (1.0 - baseColor) * pow5(1.0 - c);
  return mix(vec3(F_Dielectric(c, iorFromF0(0.04))), metal, metalness);
#else
  return F_Schlick(f0FromMaterial(baseColor, metalness), c);
#endif
}

// Cook-Torrance specular plus a diffuse lobe weighted by (1 - metalness); returns f_d + f_s. The default diffuse
// weight (1 - F(n.v)) takes Fresnel at the view angle, the share of light the specular lobe can take at most:
// weighting by F(v.h) instead gives a white dielectric an albedo up to 1.7 at grazing views.
vec3 brdfCookTorrance(vec3 N, vec3 V, vec3 L, float NoV, vec3 baseColor, float roughness, float metalness) {
  vec3 H = normalize(V + L);
  vec3 NxH = cross(N, H);
  float NoL = max(dot(N, L), 0.0);
  float NoH = clamp(dot(N, H), 0.0, 1.0);
  float VoH = clamp(dot(V, H), 0.0, 1.0);
  float a = alphaFromRoughness(roughness);
  vec3 specular = distribution(NoH, dot(NxH, NxH), a) * visibility(NoV, NoL, a) * fresnel(baseColor, metalness, VoH);
#if DIFFUSE == 1
  vec3 diffuse = (1.0 - metalness) * baseColor / PI;
#elif DIFFUSE == 2
  vec3 diffuse = burleyDiffuse(NoV, NoL, VoH, max(roughness, MIN_ROUGHNESS)) * (1.0 - metalness) * baseColor / PI;
#else
  vec3 diffuse = (1.0 - fresnel(baseColor, metalness, NoV)) * (1.0 - metalness) * baseColor / PI;
#endif
  return diffuse + specular;
}
