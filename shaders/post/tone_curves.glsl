// The tone curves other than ACES Hill (aces.glsl), each from its published definition: linear radiance times the
// exposure in, display-linear values in [0, 1] out, per channel unless said.

// Narkowicz 2015, "ACES Filmic Tone Mapping Curve": the RRT + ODT fitted per channel, on 0.6 x the input.
vec3 acesNarkowicz(vec3 x) {
  x *= 0.6;
  return clamp(x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

// Khronos PBR Neutral (KhronosGroup/ToneMapping, PBR_Neutral/README.md): F90 = 0.04, Ks = 0.8 - F90, Kd = 0.15.
vec3 khronosNeutral(vec3 c) {
  const float F90 = 0.04, KS = 0.8 - F90, KD = 0.15;
  float x = min(c.r, min(c.g, c.b));
  float f = x <= 2.0 * F90 ? x - x * x / (4.0 * F90) : F90;
  vec3 shifted = c - f;
  float p = max(shifted.r, max(shifted.g, shifted.b));
  if (p <= KS) return clamp(shifted, 0.0, 1.0);
  float pn = 1.0 - (1.0 - KS) * (1.0 - KS) / (p + 1.0 - 2.0 * KS);
  float g = 1.0 / (KD * (p - pn) + 1.0);
  return clamp(shifted * (pn / p) * g + vec3(pn) * (1.0 - g), 0.0, 1.0);
}

// Reinhard et al. 2002, "Photographic Tone Reproduction for Digital Images", eq. 4 with the white point
// L_white = 4: x (1 + x / L_white^2) / (1 + x), reaching 1 at the white point.
vec3 reinhard(vec3 x) {
  const float WHITE = 4.0;
  return clamp(x * (1.0 + x / (WHITE * WHITE)) / (1.0 + x), 0.0, 1.0);
}

// The seeds' exponential exposure curve: 1 - e^(-x).
vec3 exponentialCurve(vec3 x) { return clamp(1.0 - exp(-x), 0.0, 1.0); }
