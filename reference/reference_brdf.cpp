#include "reference/reference_brdf.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <stdexcept>
#include <vector>

#include <glm/geometric.hpp>

namespace pbr::reference {

BrdfForms::BrdfForms(const ShadingVariant& variant) : ShadingVariant(variant) {
  if (ndf != Ndf::Ggx) throw std::invalid_argument("the reference cannot evaluate ndf=beckmann (it has GGX alone)");
  if (diffuse == Diffuse::Burley) {
    throw std::invalid_argument("the reference cannot evaluate diffuse=burley (lambert-1-f, lambert-1-f-vh, lambert)");
  }
}

BrdfForms BrdfForms::study() { return BrdfForms(parseShadingVariant("study")); }

// Walter et al. 2007, "Microfacet Models for Refraction through Rough Surfaces".
double ggxD(double NoH, double alpha) {
  const double a2 = alpha * alpha;
  const double d = NoH * NoH * (a2 - 1.0) + 1.0;
  return a2 / (kPi * d * d);
}

double alphaFromRoughness(double roughness) {
  const double r = std::max(roughness, kMinRoughness);
  return r * r;
}

// KHR_materials_ior: F0 = ((ior - 1) / (ior + 1))^2, written as a quotient of squares so that ior 1.5 gives
// 0.25 / 6.25, the double nearest 0.04; KHR_materials_specular: times the colour, clamped to 1, times the strength.
dvec3 dielectricF0(const ReferenceMaterial& m) {
  const double f0 = (m.ior - 1.0) * (m.ior - 1.0) / ((m.ior + 1.0) * (m.ior + 1.0));
  return glm::min(f0 * m.specularColor, dvec3(1.0)) * m.specular;
}

dvec3 specularF0(const ReferenceMaterial& m) {
  return (1.0 - m.metalness) * dielectricF0(m) + m.metalness * m.baseColor;
}

// Heitz 2014, "Understanding the Masking-Shadowing Function", eq. 72: GGX's Lambda(theta) =
// (sqrt(1 + alpha^2 tan^2 theta) - 1) / 2 and G1 = 1 / (1 + Lambda).
double smithG1(double NoX, double alpha) {
  const double tan2 = (1.0 - NoX * NoX) / (NoX * NoX);
  return 1.0 / (1.0 + 0.5 * (std::sqrt(1.0 + alpha * alpha * tan2) - 1.0));
}

// Heitz 2014, "Understanding the Masking-Shadowing Function": G2 / (4 n.l n.v), height-correlated.
double smithVisibilityExact(double NoV, double NoL, double alpha) {
  const double a2 = alpha * alpha;
  const double lv = NoL * std::sqrt(NoV * NoV * (1.0 - a2) + a2);
  const double ll = NoV * std::sqrt(NoL * NoL * (1.0 - a2) + a2);
  return 0.5 / (lv + ll);
}

// Hammon 2017, "PBR Diffuse Lighting for GGX+Smith": the height-correlated form, linear in alpha between its
// limits 1 / (2 (n.l + n.v)) at alpha = 1 and 1 / (4 n.l n.v) at alpha = 0.
double smithVisibilityHammon(double NoV, double NoL, double alpha) {
  return 0.5 / ((1.0 - alpha) * 2.0 * NoL * NoV + alpha * (NoL + NoV));
}

// Heitz 2014, "Understanding the Masking-Shadowing Function": uncorrelated masking and shadowing, G1(v) G1(l).
double smithVisibilitySeparable(double NoV, double NoL, double alpha) {
  return smithG1(NoV, alpha) * smithG1(NoL, alpha) / (4.0 * NoL * NoV);
}

// Cook & Torrance 1982, "A Reflectance Model for Computer Graphics", unpolarised dielectric Fresnel.
double fresnelDielectric(double c, double eta) {
  const double g2 = eta * eta - 1.0 + c * c;
  if (g2 < 0.0) return 1.0;
  const double g = std::sqrt(g2);
  const double a = (g - c) / (g + c);
  const double b = (c * (g + c) - 1.0) / (c * (g - c) + 1.0);
  return 0.5 * a * a * (1.0 + b * b);
}

double iorFromF0(double f0) {
  const double s = std::sqrt(std::clamp(f0, 0.0, 0.999));
  return (1.0 + s) / (1.0 - s);
}

// Schlick 1994, "An Inexpensive BRDF Model for Physically-based Rendering".
double fresnelSchlick(double c, double f0) { return f0 + (1.0 - f0) * std::pow(1.0 - c, 5.0); }

// Karis 2013, "Real Shading in Unreal Engine 4": (1 - c)^5 replaced by 2^((-5.55473 c - 6.98316) c).
double fresnelSchlickSG(double c, double f0) {
  return f0 + (1.0 - f0) * std::exp2((-5.55473 * c - 6.98316) * c);
}

namespace {

// The dielectric and metal parts' Fresnel reflectance apart, at incidence cosine c: KHR_materials_specular weights
// the diffuse lobe by the dielectric Fresnel's largest channel, and F90 is the dielectric's `specular` where a
// metal's is 1. Schlick's forms scale from F0 to F90 (F0 + (F90 - F0) s(c) = F90 (F0 / F90 + (1 - F0 / F90) s(c)));
// the exact form takes each channel's index of refraction from F0 / F90 and scales by F90 the same way.
void fresnelParts(double c, const ReferenceMaterial& m, const BrdfForms& forms, dvec3& dielectricPart,
                  dvec3& metalPart) {
  const dvec3 dielectric = dielectricF0(m);
  const auto schlick = [&](double f0, double f90) {
    switch (forms.fresnel) {
      case Fresnel::SchlickSG: return f90 > 0.0 ? f90 * fresnelSchlickSG(c, f0 / f90) : 0.0;
      case Fresnel::Schlick:
      case Fresnel::Exact: break;
    }
    return f90 > 0.0 ? f90 * fresnelSchlick(c, f0 / f90) : 0.0;
  };
  const auto exact = [&](double f0, double f90) {
    return f90 > 0.0 ? f90 * fresnelDielectric(c, iorFromF0(f0 / f90)) : 0.0;
  };
  for (int i = 0; i < 3; ++i) {
    dielectricPart[i] = forms.fresnel == Fresnel::Exact ? exact(dielectric[i], m.specular)
                                                        : schlick(dielectric[i], m.specular);
    // Metals take Schlick from their base colour, or its spherical-Gaussian fit with the SG variant.
    metalPart[i] = forms.fresnel == Fresnel::SchlickSG ? fresnelSchlickSG(c, m.baseColor[i])
                                                       : fresnelSchlick(c, m.baseColor[i]);
  }
}

// The largest channel of the dielectric's Fresnel reflectance: glTF's fresnel_mix weights the base by 1 - max_value(F)
// (grey for the core material, where it changes nothing).
double largestDielectricFresnel(double c, const ReferenceMaterial& m, const BrdfForms& forms) {
  dvec3 d(0.0), metal(0.0);
  fresnelParts(c, m, forms, d, metal);
  return std::max({d.x, d.y, d.z});
}

double visibilityForm(double NoV, double NoL, double a, const BrdfForms& forms) {
  switch (forms.visibility) {
    case Visibility::Hammon: return smithVisibilityHammon(NoV, NoL, a);
    case Visibility::Separable: return smithVisibilitySeparable(NoV, NoL, a);
    case Visibility::HeightCorrelated: break;
  }
  return smithVisibilityExact(NoV, NoL, a);
}

// KHR_materials_sheen's albedo scaling of the base, 1 - max(sheenColor) E(n.v) (1 without a sheen).
double sheenScaling(double NoV, const ReferenceMaterial& m) {
  if (m.sheenColor == dvec3(0.0)) return 1.0;
  return 1.0 - std::max({m.sheenColor.x, m.sheenColor.y, m.sheenColor.z}) * sheenAlbedo(NoV, m.sheenRoughness);
}

// KHR_materials_clearcoat's fresnel_coat weight, clearcoat Fc(n.v) with Schlick's term at F0 0.04, the
// specification's implementation (0 without a coat).
double coatWeight(double NoV, const ReferenceMaterial& m) {
  return m.clearcoat > 0.0 ? m.clearcoat * fresnelSchlick(NoV, 0.04) : 0.0;
}

// What the layers over the base leave of it at n.v: the sheen's scaling and the coat's 1 - Fc.
double baseLayerWeight(double NoV, const ReferenceMaterial& m) {
  return sheenScaling(NoV, m) * (1.0 - coatWeight(NoV, m));
}

}  // namespace

BrdfLobes evaluateBrdf(const dvec3& N, const dvec3& V, const dvec3& L, const ReferenceMaterial& m,
                       const BrdfForms& forms) {
  if (forms.ndf != Ndf::Ggx) throw std::logic_error("the reference has GGX alone (BrdfForms refuses another NDF)");
  const dvec3 H = glm::normalize(V + L);
  const double NoV = std::max(glm::dot(N, V), 1e-4);
  const double NoL = std::max(glm::dot(N, L), 0.0);
  const double NoH = std::clamp(glm::dot(N, H), 0.0, 1.0);
  const double VoH = std::clamp(glm::dot(V, H), 0.0, 1.0);
  const double alpha = alphaFromRoughness(m.roughness);
  auto fresnel = [&](double c) {
    dvec3 d(0.0), metal(0.0);
    fresnelParts(c, m, forms, d, metal);
    return (1.0 - m.metalness) * d + m.metalness * metal;
  };
  auto diffuseFresnel = [&](double c) {
    dvec3 d(0.0), metal(0.0);
    fresnelParts(c, m, forms, d, metal);
    const double largest = std::max({d.x, d.y, d.z});
    return (1.0 - m.metalness) * dvec3(largest) + m.metalness * metal;
  };
  auto visibility = [&](double a) { return visibilityForm(NoV, NoL, a, forms); };
  auto diffuseWeight = [&] {
    switch (forms.diffuse) {
      case Diffuse::LambertOneMinusFVh: return dvec3(1.0) - diffuseFresnel(VoH);
      case Diffuse::Lambert: return dvec3(1.0);
      case Diffuse::LambertOneMinusF: break;
      case Diffuse::Burley: throw std::logic_error("the reference has no Burley diffuse (BrdfForms refuses it)");
    }
    return dvec3(1.0) - diffuseFresnel(NoV);
  };
  dvec3 specular = ggxD(NoH, alpha) * visibility(alpha) * fresnel(VoH);
  // KHR_materials_transmission: the base is mix(diffuse, specular_btdf, transmission); the BTDF is transmissionLobe.
  dvec3 diffuse = diffuseWeight() * (1.0 - m.metalness) * (1.0 - m.transmission) * m.baseColor / kPi;
  dvec3 sheen(0.0);
  if (m.sheenColor != dvec3(0.0)) {
    const double scaling = sheenScaling(NoV, m);
    diffuse *= scaling;
    specular *= scaling;
    sheen = m.sheenColor * sheenDistribution(NoH, m.sheenRoughness) * sheenVisibility(NoV, NoL, m.sheenRoughness);
  }
  if (m.clearcoat <= 0.0) return {diffuse, specular, 0.0, sheen};
  // KHR_materials_clearcoat: fresnel_coat over everything else; the coat's lobe is the specular BRDF of its
  // roughness without a Fresnel term.
  const double coatAlpha = alphaFromRoughness(m.clearcoatRoughness);
  const double weight = coatWeight(NoV, m);
  return {(1.0 - weight) * diffuse, (1.0 - weight) * specular, weight * ggxD(NoH, coatAlpha) * visibility(coatAlpha),
          (1.0 - weight) * sheen};
}

dvec3 transmissionLobe(const dvec3& N, const dvec3& V, const dvec3& L, const ReferenceMaterial& m,
                       const BrdfForms& forms) {
  const double NoL = -glm::dot(N, L);
  if (m.transmission <= 0.0 || NoL <= 0.0) return dvec3(0.0);
  const double NoV = std::max(glm::dot(N, V), 1e-4);
  const dvec3 mirrored = L + 2.0 * NoL * N;
  const dvec3 H = glm::normalize(V + mirrored);
  const double NoH = std::clamp(glm::dot(N, H), 0.0, 1.0);
  const double VoH = std::clamp(glm::dot(V, H), 0.0, 1.0);
  const double alpha = alphaFromRoughness(m.roughness);
  const double f = ggxD(NoH, alpha) * visibilityForm(NoV, NoL, alpha, forms);
  return (1.0 - largestDielectricFresnel(VoH, m, forms)) * m.transmission * (1.0 - m.metalness) * f *
         baseLayerWeight(NoV, m) * m.baseColor;
}

dvec3 smoothTransmittance(const dvec3& N, const dvec3& V, const ReferenceMaterial& m, const BrdfForms& forms) {
  if (m.transmission <= 0.0) return dvec3(0.0);
  const double NoV = std::max(glm::dot(N, V), 1e-4);
  return (1.0 - largestDielectricFresnel(NoV, m, forms)) * m.transmission * (1.0 - m.metalness) *
         baseLayerWeight(NoV, m) * m.baseColor;
}

dvec3 sampledTransmittance(const dvec3& N, const dvec3& V, const dvec3& H, const ReferenceMaterial& m,
                           const BrdfForms& forms, dvec3& L) {
  const dvec3 reflected = 2.0 * glm::dot(V, H) * H - V;
  const double NoR = glm::dot(N, reflected);
  L = reflected - 2.0 * NoR * N;
  if (m.transmission <= 0.0 || NoR <= 0.0) return dvec3(0.0);
  const double NoV = std::max(glm::dot(N, V), 1e-4);
  const double NoH = std::clamp(glm::dot(N, H), 1e-8, 1.0);
  const double VoH = std::clamp(glm::dot(V, H), 0.0, 1.0);
  const double alpha = alphaFromRoughness(m.roughness);
  // f |n.l| / pdf with pdf = D(h) n.h / (4 v.h): D cancels.
  const double weight = visibilityForm(NoV, NoR, alpha, forms) * 4.0 * NoR * VoH / NoH;
  return (1.0 - largestDielectricFresnel(VoH, m, forms)) * m.transmission * (1.0 - m.metalness) * weight *
         baseLayerWeight(NoV, m) * m.baseColor;
}

namespace {

double sheenAlpha(double sheenRoughness) { return std::clamp(sheenRoughness, kMinSheenRoughness, 1.0); }

// Conty Estevez and Kulla 2017, "Production Friendly Microfacet Sheen BRDF": the fit of Lambda's exponent.
double sheenL(double x, double alpha) {
  const double t = (1.0 - alpha) * (1.0 - alpha);
  const double a = 21.5473 + (25.3245 - 21.5473) * t, b = 3.82987 + (3.32435 - 3.82987) * t,
               c = 0.19823 + (0.16801 - 0.19823) * t, d = -1.97760 + (-1.27393 + 1.97760) * t,
               e = -4.32054 + (-4.85967 + 4.32054) * t;
  return a / (1.0 + b * std::pow(x, c)) + d * x + e;
}

double sheenLambda(double cosTheta, double alpha) {
  return std::abs(cosTheta) < 0.5 ? std::exp(sheenL(cosTheta, alpha))
                                  : std::exp(2.0 * sheenL(0.5, alpha) - sheenL(1.0 - cosTheta, alpha));
}

}  // namespace

// Conty Estevez and Kulla 2017, as KHR_materials_sheen writes it: (2 + 1 / r) sin(h)^(1 / r) / (2 pi).
double sheenDistribution(double NoH, double sheenRoughness) {
  const double invR = 1.0 / sheenAlpha(sheenRoughness);
  const double sin2h = std::max(1.0 - NoH * NoH, 0.0);
  return (2.0 + invR) * std::pow(sin2h, 0.5 * invR) / (2.0 * kPi);
}

double sheenVisibility(double NoV, double NoL, double sheenRoughness) {
  const double alpha = sheenAlpha(sheenRoughness);
  return 1.0 / ((1.0 + sheenLambda(NoV, alpha) + sheenLambda(NoL, alpha)) * (4.0 * NoV * NoL));
}

double sheenAlbedo(double NoV, double sheenRoughness) {
  // 128 n.v bins per roughness, each the integral by a 128 x 128 midpoint rule in (cos^2 theta, phi) of D V n.l
  // against the cosine-weighted pdf n.l / pi: E = pi mean(D V).
  constexpr int kBins = 128, kSteps = 128;
  static std::mutex mutex;
  static std::map<double, std::vector<double>> tables;  // entries are never removed: a pointer to one stays valid
  const double r = sheenAlpha(sheenRoughness);
  const std::vector<double>* found = nullptr;
  {
    const std::lock_guard<std::mutex> lock(mutex);
    const auto it = tables.find(r);
    if (it != tables.end()) found = &it->second;
  }
  if (!found) {
    std::vector<double> table;
    for (int b = 0; b < kBins; ++b) {
      const double cv = std::max(double(b) / (kBins - 1), 1e-4);
      const dvec3 V(std::sqrt(1.0 - cv * cv), 0.0, cv);
      double sum = 0.0;
      for (int i = 0; i < kSteps; ++i) {
        const double u = (i + 0.5) / kSteps, sinL = std::sqrt(u), cosL = std::sqrt(1.0 - u);
        for (int j = 0; j < kSteps; ++j) {
          const double phi = 2.0 * kPi * (j + 0.5) / kSteps;
          const dvec3 L(sinL * std::cos(phi), sinL * std::sin(phi), cosL);
          const dvec3 H = glm::normalize(V + L);
          sum += sheenDistribution(H.z, r) * sheenVisibility(cv, cosL, r);
        }
      }
      table.push_back(kPi * sum / (double(kSteps) * kSteps));
    }
    const std::lock_guard<std::mutex> lock(mutex);
    found = &tables.emplace(r, std::move(table)).first->second;  // another thread's, if it came first
  }
  const std::vector<double>& table = *found;
  const double x = std::clamp(NoV, 0.0, 1.0) * (kBins - 1);
  const int i = std::min(int(x), kBins - 2);
  return table[size_t(i)] + (x - i) * (table[size_t(i) + 1] - table[size_t(i)]);
}

// Karis 2013, "Real Shading in Unreal Engine 4": the window (1 - (d / R)^4)^2 brings 1 / d^2 to 0 at R.
double attenuation(double d, double radius) {
  if (!(radius > 0.0)) return 0.0;
  const double x = d / radius;
  const double window = std::clamp(1.0 - x * x * x * x, 0.0, 1.0);
  const double dc = std::max(d, 0.01);
  return std::min(window * window / (dc * dc), 1.0);
}

}  // namespace pbr::reference
