// Importance sampling of the renderer's GGX distribution (lighting/brdf.glsl) with a low-discrepancy sequence.
#include "../lighting/brdf.glsl"

// Point i of the n-point Hammersley set: the radical inverse of i in base 2 (bitfieldReverse) against
// (i + 0.5) / n (Dammertz 2012, "Hammersley Points on the Hemisphere").
vec2 hammersley(uint i, uint n) {
  return vec2((float(i) + 0.5) / float(n), float(bitfieldReverse(i)) * 2.3283064365386963e-10);
}

// A GGX half vector in the frame where the normal is +Z, with its cosine and squared sine.
struct GgxHalfVector {
  vec3 H;
  float NoH;
  float sin2;  // |N x H|^2, as D_GGX takes it
};

// Inverts the GGX CDF: cos^2 theta = (1 - u) / (1 + (a^2 - 1) u) (Walter et al. 2007, "Microfacet Models for
// Refraction through Rough Surfaces"; Karis 2013, "Real Shading in Unreal Engine 4"). sin^2 theta =
// a^2 u / (1 + (a^2 - 1) u) is formed directly: 1 - cos^2 would lose its digits for small a.
GgxHalfVector sampleGgxHalfVector(vec2 xi, float a) {
  float a2 = a * a;
  float denom = 1.0 + (a2 - 1.0) * xi.y;
  float cos2 = (1.0 - xi.y) / denom;
  float sin2 = a2 * xi.y / denom;
  float phi = 2.0 * PI * xi.x;
  float sinTheta = sqrt(sin2);
  GgxHalfVector h;
  h.NoH = sqrt(cos2);
  h.sin2 = sin2;
  h.H = vec3(sinTheta * cos(phi), sinTheta * sin(phi), h.NoH);
  return h;
}

// An orthonormal basis with n as its third axis (Duff et al. 2017, "Building an Orthonormal Basis, Revisited",
// listing 3). It turns where n.z changes sign, which isotropic lobes do not see.
mat3 basisAround(vec3 n) {
  float s = n.z >= 0.0 ? 1.0 : -1.0;
  float a = -1.0 / (s + n.z);
  float b = n.x * n.y * a;
  return mat3(vec3(1.0 + s * n.x * n.x * a, s * b, -s * n.x), vec3(b, s + n.y * n.y * a, -n.y), n);
}

// A GGX normal distributed as the normals visible from V, D(h) G1(v) (v.h) / (n.v), in the frame where the
// normal is +Z (Heitz 2018, "Sampling the GGX Distribution of Visible Normals", listing 1).
vec3 sampleGgxVisibleNormal(vec3 V, vec2 xi, float a) {
  vec3 Vh = normalize(vec3(a * V.xy, V.z));
  float lensq = dot(Vh.xy, Vh.xy);
  vec3 T1 = lensq > 0.0 ? vec3(-Vh.y, Vh.x, 0.0) * inversesqrt(lensq) : vec3(1.0, 0.0, 0.0);
  vec3 T2 = cross(Vh, T1);
  float r = sqrt(xi.x);
  float phi = 2.0 * PI * xi.y;
  float t1 = r * cos(phi);
  float s = 0.5 * (1.0 + Vh.z);
  float t2 = mix(sqrt(1.0 - t1 * t1), r * sin(phi), s);
  vec3 Nh = t1 * T1 + t2 * T2 + sqrt(max(0.0, 1.0 - t1 * t1 - t2 * t2)) * Vh;
  return normalize(vec3(a * Nh.xy, max(0.0, Nh.z)));
}

// Smith masking of GGX, G1 = 2 n.v / (n.v + sqrt(a^2 + (1 - a^2) n.v^2)) (Heitz 2014, "Understanding the
// Masking-Shadowing Function in Microfacet-Based BRDFs"): the form of V_SmithGGXCorrelated's terms.
float G1_SmithGGX(float NoV, float a) {
  float a2 = a * a;
  return 2.0 * NoV / (NoV + sqrt((NoV - a2 * NoV) * NoV + a2));
}
