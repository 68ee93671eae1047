#pragma once
#include <glm/vec3.hpp>

namespace pbr::reference {

using glm::dvec3;

// The reference PBR model in double precision, written from the equations and sharing no code with the shaders:
// GGX NDF, exact height-correlated Smith visibility, exact unpolarised Fresnel for the dielectric part (index of
// refraction from F0 = 0.04) and Schlick for the metallic part, Lambert weighted by (1 - F(n.v)).
struct ReferenceMaterial {
  dvec3 baseColor{0.8};
  double roughness = 0.5;  // perceptual; alpha = roughness^2 (clamped like the renderer, see kMinRoughness)
  double metalness = 0.0;
};

// The renderer clamps perceptual roughness to this; the reference does too, so both describe the same surface.
constexpr double kMinRoughness = 0.045;

double ggxD(double NoH, double alpha);
double smithVisibilityExact(double NoV, double NoL, double alpha);
// Unpolarised Fresnel reflectance of a dielectric of relative index `eta` at incidence cosine `c`.
double fresnelDielectric(double c, double eta);
double iorFromF0(double f0);

struct BrdfLobes {
  dvec3 diffuse;
  dvec3 specular;
  dvec3 sum() const { return diffuse + specular; }
};

// f_d and f_s for unit vectors N, V, L (n.l > 0; n.v is clamped to 1e-4 like the renderer does).
BrdfLobes evaluateBrdf(const dvec3& N, const dvec3& V, const dvec3& L, const ReferenceMaterial& m);

// Windowed inverse-square falloff, capped at 1.
double attenuation(double d, double radius);

}  // namespace pbr::reference
