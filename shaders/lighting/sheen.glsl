// KHR_materials_sheen's fibre lobe: the "Charlie" distribution and visibility of Conty Estevez and Kulla 2017,
// "Production Friendly Microfacet Sheen BRDF", as the extension writes them. The roughness is clamped to
// [SHEEN_MIN_ROUGHNESS, 1], where the exponent 1 / r and the fitted Lambda hold (the CPU reference does the same).
#include "../common/math.glsl"

const float SHEEN_MIN_ROUGHNESS = 0.07;

float sheenAlpha(float roughness) { return clamp(roughness, SHEEN_MIN_ROUGHNESS, 1.0); }

// (2 + 1 / r) sin(h)^(1 / r) / (2 pi), sin2 = 1 - n.h^2 passed in as D_GGX takes it.
float D_Charlie(float sin2, float r) {
  float invR = 1.0 / r;
  return (2.0 + invR) * pow(max(sin2, 0.0), 0.5 * invR) / (2.0 * PI);
}

float sheenL(float x, float r) {
  float t = (1.0 - r) * (1.0 - r);
  float a = mix(21.5473, 25.3245, t), b = mix(3.82987, 3.32435, t), c = mix(0.19823, 0.16801, t);
  float d = mix(-1.97760, -1.27393, t), e = mix(-4.32054, -4.85967, t);
  return a / (1.0 + b * pow(x, c)) + d * x + e;
}

float sheenLambda(float cosTheta, float r) {
  return abs(cosTheta) < 0.5 ? exp(sheenL(cosTheta, r)) : exp(2.0 * sheenL(0.5, r) - sheenL(1.0 - cosTheta, r));
}

// 1 / ((1 + Lambda(n.v) + Lambda(n.l)) 4 n.v n.l).
float V_Charlie(float NoV, float NoL, float r) {
  return 1.0 / ((1.0 + sheenLambda(NoV, r) + sheenLambda(NoL, r)) * (4.0 * NoV * NoL));
}
