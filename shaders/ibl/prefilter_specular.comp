#version 450 core
// One level of the GGX-prefiltered specular cube map: each texel is the environment convolved with the GGX lobe
// of the level's roughness, under the split-sum assumption N = V = R (Karis 2013, "Real Shading in Unreal
// Engine 4"), weighted by n.l. Samples read the environment's mip chain at the level whose texels match their
// share of the lobe (filtered importance sampling), so a sun smaller than the sample spacing is spread over the
// lobe instead of lighting a few texels: no fireflies, down to 16 samples (ibl/README.md).
layout(local_size_x = 8, local_size_y = 8) in;

#include "cube_map.glsl"
#include "ggx_sampling.glsl"

// Mirrors the PrefilterPassBlock of ibl/prefilter_levels.cpp; the precomputation runs alone, hence binding 0.
layout(std140, binding = 0) uniform PrefilterPassBlock {
  ivec4 sizes;   // x: face size of this level, y: samples per texel, z: face size of the environment's level 0
  vec4 params;   // x: perceptual roughness of this level
} pass;

layout(binding = 0) uniform samplerCube environment;  // full mip chain, trilinear, seamless
layout(rgba16f, binding = 0) uniform writeonly imageCube prefiltered;

// Source level for a sample of density pdf among n: lod = 0.5 log2(omega_s / omega_p) + 1, omega_s = 1 / (n pdf)
// the sample's solid angle, omega_p the solid angle of a level-0 texel around L (Colbert & Krivanek, GPU Gems 3,
// ch. 20, "Mipmap Filtered Samples").
float sourceLod(vec3 L, float pdf, uint n) {
  float omegaS = 1.0 / (float(n) * pdf);
  float omegaP = cubeTexelSolidAngleAt(L, pass.sizes.z);
  return max(0.5 * log2(omegaS / omegaP) + 1.0, 0.0);
}

void main() {
  ivec3 texel = ivec3(gl_GlobalInvocationID);
  if (texel.x >= pass.sizes.x || texel.y >= pass.sizes.x) return;
  vec3 N = cubeTexelDirection(texel, pass.sizes.x);
  mat3 toWorld = basisAround(N);
  float a = alphaFromRoughness(pass.params.x);
  uint n = uint(pass.sizes.y);
  vec3 sum = vec3(0.0);
  float weight = 0.0;
  for (uint i = 0u; i < n; ++i) {
    GgxHalfVector h = sampleGgxHalfVector(hammersley(i, n), a);
    // With V = N, v.h = n.h and L = 2 (n.h) H - N, so n.l = 2 (n.h)^2 - 1.
    float NoL = 2.0 * h.NoH * h.NoH - 1.0;
    if (NoL <= 0.0) continue;
    vec3 L = toWorld * (2.0 * h.NoH * h.H - vec3(0.0, 0.0, 1.0));
    // pdf(L) = D(h) n.h / (4 v.h) = D(h) / 4 with v.h = n.h (Walter et al. 2007: the half-vector density times
    // the Jacobian of reflection).
    float pdf = D_GGX(h.NoH, h.sin2, a) * 0.25;
    sum += textureLod(environment, L, sourceLod(L, pdf, n)).rgb * NoL;
    weight += NoL;
  }
  imageStore(prefiltered, texel, vec4(min(sum / weight, vec3(FP16_MAX)), 1.0));
}
