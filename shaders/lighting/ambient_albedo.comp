#version 450 core
// The directional albedo of the shading variant's own BRDF (the defines of lighting/brdf.glsl), tabulated over
// n.v = x / (size - 1) and perceptual roughness y / (size - 1), for uniform ambient light: the integral of
// f n.l over the hemisphere is what a surface reflects of uniform radiance. Fresnel is linear in the base colour
// and metalness, so four numbers per texel give any material exactly:
//   x = A, y = B: the specular lobe with a metal's Fresnel F0 + (1 - F0) g(v.h) split as F0 A + B
//   z = C:        the specular lobe with the dielectric Fresnel (F0 0.04, or the exact term)
//   w = W:        the diffuse weight's cosine-weighted mean for a dielectric (Burley, (1 - F(v.h)))
// so that albedo = (1 - m) C + m (baseColor A + B) + W (1 - m) baseColor (model_pbr.glsl).
layout(local_size_x = 8, local_size_y = 8) in;

#include "../ibl/ggx_sampling.glsl"

// The table block of core/gl/square_table.hpp; the precomputation runs alone, hence binding 0.
layout(std140, binding = 0) uniform AmbientAlbedoBlock {
  ivec4 sizes;  // x: table size, y: samples per texel
} pass;

layout(rgba32f, binding = 0) uniform writeonly image2D table;

// The weight g(c) that takes Fresnel from F0 to 1 in the variant's form (the exact form keeps Schlick's for metals).
float fresnelWeight(float c) {
#if defined(FRESNEL_SCHLICK_SG)
  return F_SchlickSG(vec3(0.0), c).x;
#else
  return pow5(1.0 - c);
#endif
}

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  int size = pass.sizes.x;
  if (p.x >= size || p.y >= size) return;
  // Shading clamps n.v to 1e-4 (lighting/gbuffer_surface.glsl), so the n.v = 0 column holds that value.
  float NoV = max(float(p.x) / float(size - 1), 1e-4);
  float roughness = float(p.y) / float(size - 1);
  float a = alphaFromRoughness(roughness);
  vec3 V = vec3(sqrt(1.0 - NoV * NoV), 0.0, NoV);
  float G1 = G1_SmithGGX(NoV, a);
  uint n = uint(pass.sizes.y);
  vec4 sum = vec4(0.0);
  for (uint i = 0u; i < n; ++i) {
    vec2 xi = hammersley(i, n);
    // Specular: GGX visible normals, pdf(l) = D_GGX G1 / (4 n.v); the variant's D and V over that pdf.
    vec3 H = sampleGgxVisibleNormal(V, xi, a);
    float VoH = dot(V, H);
    float NoL = 2.0 * VoH * H.z - NoV;  // L = reflect(-V, H)
    if (NoL > 0.0) {
      float sin2 = dot(H.xy, H.xy);
      float w = distribution(H.z, sin2, a) * visibility(NoV, NoL, a) * NoL * 4.0 * NoV /
                (D_GGX(H.z, sin2, a) * G1);
      float g = fresnelWeight(VoH);
      sum.xyz += w * vec3(1.0 - g, g, fresnel(vec3(0.04), 0.0, VoH).x);
    }
    // Diffuse: cosine-weighted L, pdf n.l / pi, so the lobe's weight alone remains (base colour and 1 - m apart).
    float r = sqrt(xi.x), phi = 2.0 * PI * xi.y;
    vec3 L = vec3(r * cos(phi), r * sin(phi), sqrt(max(0.0, 1.0 - xi.x)));
    vec3 Hd = normalize(V + L);
    sum.w += diffuseLobe(vec3(1.0), 0.0, roughness, NoV, L.z, clamp(dot(V, Hd), 0.0, 1.0)).x * PI;
  }
  imageStore(table, p, sum / float(n));
}
