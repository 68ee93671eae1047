// The Blinn-Phong shading model of a classic LDR renderer (Blinn 1977, "Models of Light Reflection for Computer
// Synthesized Pictures"): light colours are LDR intensities, the result is clamped to [0,1], no tone mapping.
#include "brdf.glsl"

vec3 shadeAmbient(Surface s) { return 0.02 * (1.0 - s.metalness) * s.baseColor * s.occlusion; }

#if !defined(BLINN_PHONG_LOBE_POW) && !defined(BLINN_PHONG_LOBE_SG)
#define BLINN_PHONG_LOBE_POW 1
#endif

// The pixel's material terms, the same for every light: computed once before the light loop, not per pair.
vec3 gDiffuse;
vec3 gSpecularColor;
float gShininess;

// The lobe (n.h)^n. BLINN_PHONG_LOBE_SG: its spherical-Gaussian fit e^(n (n.h - 1)) (Karis 2012, "Spherical
// Gaussian approximation for Blinn-Phong, Phong and Fresnel"), one exp2 where pow takes a log2 and an exp2. Since
// x - 1 >= ln x it is never darker: equal at n.h = 1, brighter by the factor e^(n (x - 1 - ln x)) ~ 1 + n (1 - x)^2 / 2
// off the peak, where the lobe has fallen to e^(-n (1 - x)).
float lobe(float NoH) {
#if defined(BLINN_PHONG_LOBE_SG)
  return exp2(gShininess * 1.4426950408889634 * (NoH - 1.0));
#else
  return pow(NoH, gShininess);
#endif
}

void beginShading(Surface s) {
  gDiffuse = (1.0 - s.metalness) * s.baseColor;
  gSpecularColor = f0FromMaterial(s.baseColor, s.metalness);
  // Shininess matching the GGX lobe width: n = 2 / a^2 - 2.
  float a = alphaFromRoughness(s.roughness);
  gShininess = 2.0 / (a * a) - 2.0;
}

// Light of LDR colour `color` from unit direction L, scaled by `weight` (a point light's attenuation).
vec3 shadeIncident(Surface s, vec3 L, vec3 color, float weight) {
  float NoL = dot(s.normal, L);
  if (NoL <= 0.0 || weight <= 0.0) return vec3(0.0);
  float NoH = max(dot(s.normal, normalize(s.V + L)), 0.0);
  return (gDiffuse * NoL + gSpecularColor * lobe(NoH)) * color * weight;
}

vec3 shadeLight(Surface s, PointLight light, vec4 cone) {
  float d2;
  vec3 L = directionToLight(s.position, s.normal, light, d2);
  return shadeIncident(s, L, light.colorIntensity.rgb, lightAttenuation(d2, L, light, cone));
}

// As a point light's intensity, a directional light's illuminance has no place in an LDR model: its colour is its
// strength.
vec3 shadeDirectional(Surface s, DirectionalLight light) {
  return shadeIncident(s, light.toLight.xyz, light.colorIlluminance.rgb, 1.0);
}

vec3 finishShading(vec3 color) { return clamp(color, 0.0, 1.0); }
