#version 450 core
// The split-sum DFG table (Karis 2013, "Real Shading in Unreal Engine 4"): for n.v = x / (size - 1) and
// perceptual roughness y / (size - 1), the directional albedo of the renderer's specular lobe (GGX D,
// height-correlated Smith V, Schlick F) split as F0 * A + B, stored (A, B). Texel centres sit on the range ends
// so that lookups at n.v = 1 or roughness 0 read exact values (see iblDfg in ibl_sample.glsl).
layout(local_size_x = 8, local_size_y = 8) in;

#include "ggx_sampling.glsl"

// The table block of core/gl/square_table.hpp; the precomputation runs alone, hence binding 0.
layout(std140, binding = 0) uniform DfgPassBlock {
  ivec4 sizes;  // x: table size, y: samples per texel
} pass;

layout(rg16f, binding = 0) uniform writeonly image2D dfg;

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  int size = pass.sizes.x;
  if (p.x >= size || p.y >= size) return;
  // Shading clamps n.v to 1e-4 (lighting/gbuffer_surface.glsl), so the n.v = 0 column holds that value.
  float NoV = max(float(p.x) / float(size - 1), 1e-4);
  float a = alphaFromRoughness(float(p.y) / float(size - 1));
  vec3 V = vec3(sqrt(1.0 - NoV * NoV), 0.0, NoV);
  float G1 = G1_SmithGGX(NoV, a);
  uint n = uint(pass.sizes.y);
  vec2 sum = vec2(0.0);
  for (uint i = 0u; i < n; ++i) {
    // Visible normals rather than D: at grazing views most GGX normals face away from V, and weighting the few
    // that do not by D-sampling's 1 / pdf leaves 512 samples 0.02 off near n.v = 0; here each sample weighs <= 1.
    vec3 H = sampleGgxVisibleNormal(V, hammersley(i, n), a);
    float VoH = dot(V, H);
    float NoL = 2.0 * VoH * H.z - NoV;  // L = reflect(-V, H)
    if (NoL <= 0.0) continue;
    // f_s n.l / pdf with pdf(l) = G1 D / (4 n.v): D cancels, leaving 4 V n.l n.v / G1 = G2 / G1, times F.
    float w = 4.0 * V_SmithGGXCorrelated(NoV, NoL, a) * NoL * NoV / G1;
    float Fc = pow5(1.0 - VoH);
    sum += vec2(1.0 - Fc, Fc) * w;
  }
  imageStore(dfg, p, vec4(sum / float(n), 0.0, 0.0));
}
