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

#ifndef VISIBILITY_FAST
#define VISIBILITY_FAST 0
#endif

float visibility(float NoV, float NoL, float a) {
#if VISIBILITY_FAST
  return V_SmithGGXCorrelatedFast(NoV, NoL, a);
#else
  return V_SmithGGXCorrelated(NoV, NoL, a);
#endif
}

// Cook-Torrance GGX specular plus Lambert diffuse weighted by (1 - F(n.v))(1 - metalness); returns f_d + f_s.
// The diffuse weight takes Fresnel at the view angle, the share of light the specular lobe can take at most:
// weighting by F(v.h) instead gives a white dielectric an albedo up to 1.7 at grazing views.
vec3 brdfCookTorrance(vec3 N, vec3 V, vec3 L, float NoV, vec3 baseColor, float roughness, float metalness) {
  vec3 H = normalize(V + L);
  vec3 NxH = cross(N, H);
  float NoL = max(dot(N, L), 0.0);
  float NoH = clamp(dot(N, H), 0.0, 1.0);
  float VoH = clamp(dot(V, H), 0.0, 1.0);
  float a = alphaFromRoughness(roughness);
  vec3 F0 = f0FromMaterial(baseColor, metalness);
  vec3 specular = D_GGX(NoH, dot(NxH, NxH), a) * visibility(NoV, NoL, a) * F_Schlick(F0, VoH);
  vec3 diffuse = (1.0 - F_Schlick(F0, NoV)) * (1.0 - metalness) * baseColor / PI;
  return diffuse + specular;
}
