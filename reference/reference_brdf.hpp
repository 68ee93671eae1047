#pragma once
#include <limits>

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
  // KHR_materials_ior and KHR_materials_specular: the dielectric part's index of refraction, specular strength
  // (specularFactor) and F0 colour (specularColorFactor); the defaults are the core glTF material's F0 0.04, F90 1.
  double ior = 1.5;
  double specular = 1.0;
  dvec3 specularColor{1.0};
  // KHR_materials_clearcoat: the coat's strength (0: none) and perceptual roughness; its normal is the surface's
  // (the reference draws no normal map).
  double clearcoat = 0.0;
  double clearcoatRoughness = 0.0;
  // KHR_materials_sheen: the fibre lobe's colour (0: none) and roughness.
  dvec3 sheenColor{0.0};
  double sheenRoughness = 0.0;
  // KHR_materials_transmission's factor and KHR_materials_volume's thickness (0: thin-walled), attenuation colour
  // and distance (infinite: no absorption).
  double transmission = 0.0;
  double thickness = 0.0;
  dvec3 attenuationColor{1.0};
  double attenuationDistance = std::numeric_limits<double>::infinity();
};

// The sheen roughness the renderer clamps to, as the reference does: the "Charlie" distribution's exponent 1 / r
// and its visibility fit are used over [0.07, 1].
constexpr double kMinSheenRoughness = 0.07;
// KHR_materials_sheen's "Charlie" distribution (Conty Estevez and Kulla 2017) and its visibility, 1 / ((1 +
// Lambda(n.v) + Lambda(n.l)) 4 n.v n.l) with the paper's fitted Lambda, both as the extension writes them.
double sheenDistribution(double NoH, double sheenRoughness);
double sheenVisibility(double NoV, double NoL, double sheenRoughness);
// E: the directional albedo of the white sheen lobe, the integral of D V n.l over the hemisphere, by quadrature
// (memoised per roughness, interpolated over n.v).
double sheenAlbedo(double NoV, double sheenRoughness);

// The renderer clamps perceptual roughness to this; the reference does too, so both describe the same surface.
constexpr double kMinRoughness = 0.045;
// The renderer's alpha for a perceptual roughness: max(roughness, kMinRoughness)^2.
double alphaFromRoughness(double roughness);
// The dielectric part's normal-incidence reflectance, min(((ior - 1) / (ior + 1))^2 specularColor, 1) specular
// (KHR_materials_specular), 0.04 for the core material; its grazing reflectance is `specular`.
dvec3 dielectricF0(const ReferenceMaterial& m);
// The normal-incidence reflectance mix(dielectricF0, baseColor, metalness) that the Schlick forms start from.
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

// The lobes at one pair of directions, each with its layer weights applied: a clear coat's `coat` lobe weighted by
// clearcoat Fc, the others by 1 - clearcoat Fc (KHR_materials_clearcoat's fresnel_coat); the `sheen` lobe added
// over the base's, which are scaled by 1 - max(sheenColor) E(n.v) (KHR_materials_sheen's albedo scaling in the
// form that depends on the view alone, which the extension allows for direct and ambient light alike).
struct BrdfLobes {
  dvec3 diffuse{0.0};
  dvec3 specular{0.0};
  double coat = 0.0;
  dvec3 sheen{0.0};
  dvec3 sum() const { return diffuse + specular + dvec3(coat) + sheen; }
};

// f_d and f_s for unit vectors N, V, L (n.l > 0; n.v is clamped to 1e-4 like the renderer does).
BrdfLobes evaluateBrdf(const dvec3& N, const dvec3& V, const dvec3& L, const ReferenceMaterial& m,
                       const BrdfForms& forms = {});

// KHR_materials_transmission's thin-walled specular_btdf f_T for light from L behind the surface (n.l < 0), which
// the light's E |n.l| multiplies. The specification's microfacet BTDF: GGX D and the form's visibility
// about the transmission half vector H_T = normalize(V + L'), L' = L mirrored through the surface's plane, weighted
// as fresnel_mix weights the base, (1 - max_value(F(v.h))) transmission (1 - metalness) baseColor, and by what a
// sheen or coat leaves of the base. 0 for light in front.
dvec3 transmissionLobe(const dvec3& N, const dvec3& V, const dvec3& L, const ReferenceMaterial& m,
                       const BrdfForms& forms = {});
// The share of the radiance behind a smooth transmissive surface that reaches V through it (the BTDF's delta
// lobe along the view): (1 - max_value(F(n.v))) transmission (1 - metalness) baseColor, times the layers' weight.
dvec3 smoothTransmittance(const dvec3& N, const dvec3& V, const ReferenceMaterial& m, const BrdfForms& forms = {});
// One importance sample of a rough thin-walled surface's BTDF: for the microfacet normal H drawn with density
// D(h) n.h, the direction L behind the surface it sends V's light from (V reflected about H, mirrored through the
// surface's plane) and the estimator's weight f_T |n.l| / pdf(L); 0 where the reflection falls below the surface.
dvec3 sampledTransmittance(const dvec3& N, const dvec3& V, const dvec3& H, const ReferenceMaterial& m,
                           const BrdfForms& forms, dvec3& L);

// Windowed inverse-square falloff, capped at 1.
double attenuation(double d, double radius);

}  // namespace pbr::reference
