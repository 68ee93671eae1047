// ACES filmic tone curve, Stephen Hill's fit of the RRT + ODT (sRGB primaries in and out).
// GLSL matrices are column-major: each line below is one column of Hill's (row-major) matrices.
const mat3 ACES_INPUT = mat3(0.59719, 0.07600, 0.02840,
                             0.35458, 0.90834, 0.13383,
                             0.04823, 0.01566, 0.83777);
const mat3 ACES_OUTPUT = mat3(1.60475, -0.10208, -0.00327,
                              -0.53108, 1.10813, -0.07276,
                              -0.07367, -0.00605, 1.07602);

vec3 rrtAndOdtFit(vec3 v) {
  vec3 a = v * (v + 0.0245786) - 0.000090537;
  vec3 b = v * (0.983729 * v + 0.4329510) + 0.238081;
  return a / b;
}

vec3 acesFitted(vec3 color) {
  color = ACES_OUTPUT * rrtAndOdtFit(ACES_INPUT * color);
  return clamp(color, 0.0, 1.0);
}
