#version 450 core
// E(n.v, r): the directional albedo of the white sheen lobe (sheen.glsl), the integral of D V n.l over the
// hemisphere, tabulated over n.v = x / (size - 1) and sheen roughness r = y / (size - 1) for KHR_materials_sheen's
// albedo scaling 1 - max(sheenColor) E(n.v) and the lobe's own ambient reflection sheenColor E(n.v).
layout(local_size_x = 8, local_size_y = 8) in;

#include "../ibl/ggx_sampling.glsl"
#include "sheen.glsl"

// The table block of core/gl/square_table.hpp; the precomputation runs alone, hence binding 0.
layout(std140, binding = 0) uniform SheenAlbedoBlock {
  ivec4 sizes;  // x: table size, y: samples per texel
} pass;

layout(r32f, binding = 0) uniform writeonly image2D table;

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  int size = pass.sizes.x;
  if (p.x >= size || p.y >= size) return;
  float NoV = max(float(p.x) / float(size - 1), 1e-4);  // shading clamps n.v to 1e-4
  float r = sheenAlpha(float(p.y) / float(size - 1));
  vec3 V = vec3(sqrt(1.0 - NoV * NoV), 0.0, NoV);
  uint n = uint(pass.sizes.y);
  float sum = 0.0;
  for (uint i = 0u; i < n; ++i) {
    // Cosine-weighted L, pdf n.l / pi: the lobe is broad, and D V pi remains.
    vec2 xi = hammersley(i, n);
    float s = sqrt(xi.x), phi = 2.0 * PI * xi.y;
    vec3 L = vec3(s * cos(phi), s * sin(phi), sqrt(max(0.0, 1.0 - xi.x)));
    vec3 H = normalize(V + L);
    if (L.z > 0.0) sum += D_Charlie(dot(H.xy, H.xy), r) * V_Charlie(NoV, L.z, r) * PI;
  }
  imageStore(table, p, vec4(sum / float(n)));
}
