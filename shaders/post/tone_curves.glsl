// The tone curves other than ACES Hill (aces.glsl), each from its published definition: linear radiance times the
// exposure in, display-linear values in [0, 1] out, per channel unless said. AgX needs srgb.glsl included first.

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

// AgX as Blender (4.0 and later) forms images: Eary Chow's AgX Base (github.com/EaryChow/AgX_LUT_Gen,
// AgXBaseRec2020.py and AgXBasesRGB.py) on Sobotka's AgX. Linear sRGB to Rec.2020 (ITU-R BT.2087), the inset
// matrix, log2 encoding from -10 to +6.5 stops around 0.18, Sobotka's port of Jed Smith's tunable sigmoid (fulcrum
// (10 / 16.5, 0.18^(1/2.4)), slope 2.4, toe and shoulder powers 1.5), decoding by the power 2.4, the outset matrix,
// Rec.2020 to sRGB. The matrices are the generator's, as Filament's ToneMapper.cpp evaluates them. Left out: the
// 40% mix of pre- and post-sigmoid HSV hue and the lower guard rail, which acts only on negative Rec.2020 values that
// non-negative sRGB radiance never makes. Blender encodes the result with the pure power 1/2.4, not the sRGB curve:
// the value returned is the one whose sRGB encoding gives that code.
// GLSL matrices are column-major: each line below is one column of the row-major matrix.
const mat3 AGX_SRGB_TO_REC2020 = mat3(0.6274039, 0.0690973, 0.0163914,
                                      0.3292830, 0.9195404, 0.0880133,
                                      0.0433131, 0.0113623, 0.8955953);
const mat3 AGX_REC2020_TO_SRGB = mat3(1.6604910, -0.1245505, -0.0181508,
                                      -0.5876411, 1.1328999, -0.1005789,
                                      -0.0728499, -0.0083494, 1.1187297);
const mat3 AGX_INSET = mat3(0.856627153315983, 0.137318972929847, 0.11189821299995,
                            0.0951212405381588, 0.761241990602591, 0.0767994186031903,
                            0.0482516061458583, 0.101439036467562, 0.811302368396859);
const mat3 AGX_OUTSET = mat3(1.1271005818144368, -0.1413297634984383, -0.14132976349843826,
                             -0.11060664309660323, 1.157823702216272, -0.11060664309660294,
                             -0.016493938717834573, -0.016493938717834257, 1.2519364065950405);
const float AGX_MIN_EV = -10.0 + log2(0.18), AGX_MAX_EV = 6.5 + log2(0.18);
const float AGX_PIVOT_X = 10.0 / 16.5, AGX_PIVOT_Y = pow(0.18, 1.0 / 2.4), AGX_SLOPE = 2.4, AGX_POWER = 1.5;

// The sigmoid's scale on one side of the fulcrum, spanning `run` of input and `rise` of output to the limit (0 or
// 1): (s run)^-p ((s run / rise)^p - 1))^(-1/p) (sigmoid.py, scale()).
float agxScale(float run, float rise) {
  return pow(pow(AGX_SLOPE * run, -AGX_POWER) * (pow(AGX_SLOPE * run / rise, AGX_POWER) - 1.0), -1.0 / AGX_POWER);
}

// y = pivot + k e(s |x - pivot| / k) on each side, e(t) = t / (1 + t^p)^(1/p), k the side's scale.
vec3 agxSigmoid(vec3 x) {
  float toe = agxScale(AGX_PIVOT_X, AGX_PIVOT_Y);
  float shoulder = agxScale(1.0 - AGX_PIVOT_X, 1.0 - AGX_PIVOT_Y);
  vec3 k = mix(vec3(shoulder), vec3(toe), lessThan(x, vec3(AGX_PIVOT_X)));
  vec3 t = AGX_SLOPE * abs(x - AGX_PIVOT_X) / k;
  vec3 e = t / pow(1.0 + pow(t, vec3(AGX_POWER)), vec3(1.0 / AGX_POWER));
  return AGX_PIVOT_Y + sign(x - AGX_PIVOT_X) * k * e;
}

vec3 agx(vec3 c) {
  vec3 v = AGX_INSET * (AGX_SRGB_TO_REC2020 * c);
  v = clamp((log2(max(v, vec3(1e-10))) - AGX_MIN_EV) / (AGX_MAX_EV - AGX_MIN_EV), 0.0, 1.0);
  v = pow(agxSigmoid(v), vec3(2.4));
  v = clamp(AGX_REC2020_TO_SRGB * (AGX_OUTSET * v), 0.0, 1.0);
  return srgbDecode(pow(v, vec3(1.0 / 2.4)));
}
