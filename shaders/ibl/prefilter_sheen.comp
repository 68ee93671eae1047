#version 450 core
// One level of the sheen's prefiltered cube map (KHR_materials_sheen under an environment): each texel is the
// environment weighted by the "Charlie" lobe of the level's sheen roughness (Conty Estevez & Kulla 2017, the
// extension's D and V) under the split-sum assumption N = V, D V n.l normalised by its own sum, so that a uniform
// environment stays itself; the sheen table's E scales it at shading time (glTF-Sample-Viewer's "charlie"
// prefilter, with its LUT). With V = N the half vector makes half L's angle to N, so the lobe over L goes as
// sin(theta_L / 2)^(1 / r) = ((1 - cos theta_L) / 2)^k, k = 1 / (2 r): it gathers towards grazing light as the
// roughness falls. The samples follow that shape, cos theta_L = 1 - (1 - xi)^(1 / (k + 1)) (its inverse CDF), each
// weighted by the lobe over its density and reading the environment's level that matches its solid angle.
layout(local_size_x = 8, local_size_y = 8) in;

#include "cube_map.glsl"
#include "ggx_sampling.glsl"
#include "../lighting/sheen.glsl"

// Mirrors the PrefilterPassBlock of ibl/prefilter_levels.cpp; the precomputation runs alone, hence binding 0.
layout(std140, binding = 0) uniform PrefilterPassBlock {
  ivec4 sizes;   // x: face size of this level, y: samples per texel, z: face size of the environment's level 0
  vec4 params;   // x: sheen roughness of this level
} pass;

layout(binding = 0) uniform samplerCube environment;  // full mip chain, trilinear, seamless
layout(rgba16f, binding = 0) uniform writeonly imageCube prefiltered;

void main() {
  ivec3 texel = ivec3(gl_GlobalInvocationID);
  if (texel.x >= pass.sizes.x || texel.y >= pass.sizes.x) return;
  vec3 N = cubeTexelDirection(texel, pass.sizes.x);
  mat3 toWorld = basisAround(N);
  float r = sheenAlpha(pass.params.x);
  uint n = uint(pass.sizes.y);
  float k = 0.5 / r;
  vec3 sum = vec3(0.0);
  float weight = 0.0;
  for (uint i = 0u; i < n; ++i) {
    vec2 xi = hammersley(i, n);
    float NoL = 1.0 - pow(1.0 - xi.x, 1.0 / (k + 1.0));
    if (NoL <= 0.0) continue;
    float sinL = sqrt(max(1.0 - NoL * NoL, 0.0)), phi = 2.0 * PI * xi.y;
    vec3 l = vec3(sinL * cos(phi), sinL * sin(phi), NoL);
    vec3 h = normalize(l + vec3(0.0, 0.0, 1.0));
    // The density over solid angle: (k + 1) (1 - cos theta_L)^k / (2 pi).
    float pdf = max((k + 1.0) * pow(1.0 - NoL, k) / (2.0 * PI), 1e-30);
    float w = D_Charlie(h.x * h.x + h.y * h.y, r) * V_Charlie(1.0, NoL, r) * NoL / pdf;
    vec3 L = toWorld * l;
    // The sample's solid angle 1 / (n pdf) against a level-0 texel's: the source level (Colbert & Krivanek, GPU
    // Gems 3, ch. 20), as the specular prefilter reads it.
    float lod = max(0.5 * log2(1.0 / (float(n) * pdf * cubeTexelSolidAngleAt(L, pass.sizes.z))) + 1.0, 0.0);
    sum += textureLod(environment, L, lod).rgb * w;
    weight += w;
  }
  imageStore(prefiltered, texel, vec4(min(sum / max(weight, 1e-30), vec3(FP16_MAX)), 1.0));
}
