#pragma once
#include <glm/vec3.hpp>

#include "core/scene/shading_model.hpp"

namespace pbr::reference {

using glm::dvec3;

constexpr double kPi = 3.14159265358979323846;

// The reference PBR model in double precision, written from the equations and sharing no code with the shaders:
// GGX NDF, exact height-correlated Smith visibility, exact unpolarised Fresnel for the dielectric part (index of
// refraction from F0 = 0.04) and Schlick for the metallic part, Lambert weighted by (1 - F(n.v)). BrdfForms swaps
// single terms for the approximations a renderer variant makes, so that the reference can render that model too.
struct ReferenceMaterial {
  dvec3 baseColor{0.8};
  double roughness = 0.5;  // perceptual; alpha = roughness^2 (clamped like the renderer, see kMinRoughness)
  double metalness = 0.0;
};

// The renderer clamps perceptual roughness to this; the reference does too, so both describe the same surface.
constexpr double kMinRoughness = 0.045;
// The renderer's alpha for a perceptual roughness: max(roughness, kMinRoughness)^2.
double alphaFromRoughness(double roughness);
// The normal-incidence reflectance mix(0.04, baseColor, metalness) that the Schlick forms start from.
dvec3 specularF0(const ReferenceMaterial& m);

// Which form of each term evaluateBrdf uses, in the renderer's vocabulary (ShadingVariant, core/scene/shading_model.hpp:
// one set of names, parsed once): visibility exact (height-correlated), hammon or separable; Fresnel exact (for
// the dielectric part, Schlick for metals), schlick or schlick-sg; diffuse lambert-1-f (by 1 - F(n.v)),
// lambert-1-f-vh or lambert, times (1 - metalness) in every case. The defaults are the reference model above, which
// differs from the renderer's default in one term by choice: Fresnel exact where the renderer's is Schlick's (the
// yardstick evaluates the exact form the approximation is measured against). The reference cannot evaluate
// ndf=beckmann nor diffuse=burley: made from a variant that uses them, BrdfForms throws std::invalid_argument naming
// the term.
struct BrdfForms : ShadingVariant {
  BrdfForms() { fresnel = Fresnel::Exact; }
  BrdfForms(const ShadingVariant& variant);  // NOLINT: a variant is a set of forms
  // The PBR model of the Blinn-Phong-vs-PBR study: Hammon, Schlick, Lambert by (1 - F(v.h)).
  static BrdfForms study();
};

double ggxD(double NoH, double alpha);
// Smith's GGX masking of one direction at cosine NoX to the normal.
double smithG1(double NoX, double alpha);
double smithVisibilityExact(double NoV, double NoL, double alpha);
double smithVisibilityHammon(double NoV, double NoL, double alpha);
double smithVisibilitySeparable(double NoV, double NoL, double alpha);
// Unpolarised Fresnel reflectance of a dielectric of relative index `eta` at incidence cosine `c`.
double fresnelDielectric(double c, double eta);
double iorFromF0(double f0);
// Schlick's reflectance at incidence cosine `c` for normal-incidence reflectance `f0`, and its spherical-Gaussian fit.
double fresnelSchlick(double c, double f0);
double fresnelSchlickSG(double c, double f0);

struct BrdfLobes {
  dvec3 diffuse;
  dvec3 specular;
  dvec3 sum() const { return diffuse + specular; }
};

// f_d and f_s for unit vectors N, V, L (n.l > 0; n.v is clamped to 1e-4 like the renderer does).
BrdfLobes evaluateBrdf(const dvec3& N, const dvec3& V, const dvec3& L, const ReferenceMaterial& m,
                       const BrdfForms& forms = {});

// Windowed inverse-square falloff, capped at 1.
double attenuation(double d, double radius);

}  // namespace pbr::reference
