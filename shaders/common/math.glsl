const float PI = 3.14159265358979;
// Largest finite half float: HDR values are clamped to it so that an RGBA16F target never holds Inf.
const float FP16_MAX = 65504.0;

float saturate(float x) { return clamp(x, 0.0, 1.0); }
float pow5(float x) { float x2 = x * x; return x2 * x2 * x; }

// The coordinates of `at` in [0,1]^2 in a lookup table of `size` texels whose texel centres lie on the range's ends
// (the square tables of core/gl/square_table.hpp).
vec2 tableUv(vec2 at, vec2 size) { return (clamp(at, 0.0, 1.0) * (size - 1.0) + 0.5) / size; }
