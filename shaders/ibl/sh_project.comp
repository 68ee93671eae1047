#version 450 core
// Projects one level of the environment cube map onto 9 spherical-harmonic coefficients, first pass: each
// invocation sums L(w) Y(w) dw over an 8x8 block of texels of one face and writes its own 9 partial sums;
// sh_reduce.comp adds them up. Texels are weighted by their exact solid angle, so a constant environment
// projects to exactly its value times 4 pi Y00. No shared-memory reduction: llvmpipe turns every barrier into a
// coroutine switch and takes seconds to compile such a shader.
layout(local_size_x = 8, local_size_y = 8) in;

#include "cube_map.glsl"
#include "sh9.glsl"

const int BLOCK = 8;

layout(rgba16f, binding = 0) uniform readonly imageCube environment;
// Nine vec4 (rgb, unused) per invocation; the precomputation runs alone, hence binding 0.
layout(std430, binding = 0) writeonly buffer Partials { vec4 partials[]; };

void main() {
  int size = imageSize(environment).x;
  int blocks = (size + BLOCK - 1) / BLOCK;
  ivec3 block = ivec3(gl_GlobalInvocationID);
  if (block.x >= blocks || block.y >= blocks) return;
  vec3 sums[9];
  for (int k = 0; k < 9; ++k) sums[k] = vec3(0.0);
  for (int y = block.y * BLOCK; y < min(block.y * BLOCK + BLOCK, size); ++y) {
    for (int x = block.x * BLOCK; x < min(block.x * BLOCK + BLOCK, size); ++x) {
      ivec3 texel = ivec3(x, y, block.z);
      float Y[9];
      shBasis9(cubeTexelDirection(texel, size), Y);
      vec3 L = imageLoad(environment, texel).rgb * cubeTexelSolidAngle(texel.xy, size);
      for (int k = 0; k < 9; ++k) sums[k] += L * Y[k];
    }
  }
  uint index = uint((block.z * blocks + block.y) * blocks + block.x);
  for (int k = 0; k < 9; ++k) partials[index * 9u + uint(k)] = vec4(sums[k], 0.0);
}
