#version 450 core
// Renders the environment into level 0 of an RGBA16F cube map: the equirectangular image (SOURCE_SKY 0) or the
// procedural sky (SOURCE_SKY 1), rotated about +Y and scaled by the intensity. Each texel averages
// subsamples x subsamples directions, so a source finer than the cube map is box-filtered, not point-sampled.
layout(local_size_x = 8, local_size_y = 8) in;

#include "cube_map.glsl"
#include "../common/math.glsl"

// Mirrors the EnvironmentPassBlock of ibl/environment_cubemap.cpp; the precomputation runs alone, hence binding 0.
layout(std140, binding = 0) uniform EnvironmentPassBlock {
  vec4 sunDirection;  // xyz: unit vector to the sun; w: its angular radius as rendered (radians)
  vec4 sunRadiance;   // rgb, as rendered
  vec4 zenith;
  vec4 horizon;
  vec4 ground;
  vec4 params;        // x: cos(rotation), y: sin(rotation), z: intensity
  ivec4 sizes;        // x: face size, y: subsamples per texel side
} pass;

layout(rgba16f, binding = 0) uniform writeonly imageCube environment;

#if SOURCE_SKY
#include "sky.glsl"
#else
layout(binding = 0) uniform sampler2D equirect;  // rows from the top (+Y), u = 0.5 looks along -Z, u = 0.75 along +X

vec3 equirectRadiance(vec3 d) {
  vec2 uv = vec2(0.5 + atan(d.x, -d.z) / (2.0 * PI), acos(clamp(d.y, -1.0, 1.0)) / PI);
  // Compute shaders have no implicit derivatives; the subsamples do the filtering.
  return textureLod(equirect, uv, 0.0).rgb;
}
#endif

void main() {
  ivec3 texel = ivec3(gl_GlobalInvocationID);
  int size = pass.sizes.x;
  if (texel.x >= size || texel.y >= size) return;
  int n = pass.sizes.y;
  float subsampleAngle = 2.0 / float(size * n);  // at the face centre, where subsamples are widest
  vec3 sum = vec3(0.0);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      vec2 st = (vec2(texel.xy) + (vec2(i, j) + 0.5) / float(n)) / float(size);
      vec3 d = normalize(cubeDirection(texel.z, st));
      // The environment turned by +angle about +Y shows at d what the source holds at d turned by -angle.
      vec3 source = vec3(pass.params.x * d.x - pass.params.y * d.z, d.y, pass.params.y * d.x + pass.params.x * d.z);
#if SOURCE_SKY
      sum += skyRadiance(source, subsampleAngle);
#else
      sum += equirectRadiance(source);
#endif
    }
  }
  vec3 radiance = sum * (pass.params.z / float(n * n));
  imageStore(environment, texel, vec4(min(radiance, vec3(FP16_MAX)), 1.0));
}
