const float PI = 3.14159265358979;
// Largest finite half float: HDR values are clamped to it so that an RGBA16F target never holds Inf.
const float FP16_MAX = 65504.0;

float saturate(float x) { return clamp(x, 0.0, 1.0); }
float pow5(float x) { float x2 = x * x; return x2 * x2 * x; }
