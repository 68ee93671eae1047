#include "reference/directional_albedo.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace pbr::reference {

namespace {

// Heitz 2018, listing 1: stretch V to the hemisphere configuration, sample the projected disk, unstretch.
dvec3 sampleVisibleNormal(const dvec3& V, double alpha, double u1, double u2) {
  const dvec3 Vh = glm::normalize(dvec3(alpha * V.x, alpha * V.y, V.z));
  const double lensq = Vh.x * Vh.x + Vh.y * Vh.y;
  const dvec3 T1 = lensq > 0.0 ? dvec3(-Vh.y, Vh.x, 0.0) / std::sqrt(lensq) : dvec3(1.0, 0.0, 0.0);
  const dvec3 T2 = glm::cross(Vh, T1);
  const double r = std::sqrt(u1), phi = 2.0 * kPi * u2;
  const double t1 = r * std::cos(phi);
  const double s = 0.5 * (1.0 + Vh.z);
  const double t2 = (1.0 - s) * std::sqrt(std::max(0.0, 1.0 - t1 * t1)) + s * r * std::sin(phi);
  const dvec3 Nh = t1 * T1 + t2 * T2 + std::sqrt(std::max(0.0, 1.0 - t1 * t1 - t2 * t2)) * Vh;
  return glm::normalize(dvec3(alpha * Nh.x, alpha * Nh.y, std::max(0.0, Nh.z)));
}

}  // namespace

dvec3 directionalAlbedo(const ReferenceMaterial& m, double NoV, const BrdfForms& forms, int samples) {
  const dvec3 N(0, 0, 1);
  const double cv = std::clamp(NoV, 1e-4, 1.0);
  const dvec3 V(std::sqrt(1.0 - cv * cv), 0.0, cv);
  const double alpha = alphaFromRoughness(m.roughness);
  // A clear coat's lobe (KHR_materials_clearcoat) is sampled by its own roughness, as the base's specular is.
  const double coatAlpha = alphaFromRoughness(m.clearcoatRoughness);
  dvec3 specular(0.0), diffuse(0.0);
  double coat = 0.0;
  // A GGX normal visible from V (Heitz 2018, "Sampling the GGX Distribution of Visible Normals"), so that
  // pdf(l) = D(h) G1(v) / (4 n.v): at grazing views D-sampling wastes most samples on normals facing away. The
  // lobes at the reflected direction, each times n.l / pdf, or nothing where it falls below the horizon.
  const auto ggxSample = [&](double a, double u1, double u2) {
    const dvec3 H = sampleVisibleNormal(V, a, u1, u2);
    const double VoH = glm::dot(V, H);
    const dvec3 L = 2.0 * VoH * H - V;
    if (L.z <= 0.0 || VoH <= 0.0) return BrdfLobes{};
    const double weight = L.z / (ggxD(H.z, a) * smithG1(cv, a) / (4.0 * cv));
    BrdfLobes lobes = evaluateBrdf(N, V, L, m, forms);
    lobes.specular *= weight;
    lobes.coat *= weight;
    return lobes;
  };
  for (int i = 0; i < samples; ++i) {
    for (int j = 0; j < samples; ++j) {
      const double u = (i + 0.5) / samples, phi = 2.0 * kPi * (j + 0.5) / samples;
      specular += ggxSample(alpha, u, (j + 0.5) / samples).specular;
      // Cosine-weighted directions: pdf(l) = n.l / pi.
      const double sinL = std::sqrt(u);
      const dvec3 Ld(sinL * std::cos(phi), sinL * std::sin(phi), std::sqrt(1.0 - u));
      // The sheen lobe (KHR_materials_sheen) is broad: cosine-weighted directions serve it too.
      const BrdfLobes cosineSampled = evaluateBrdf(N, V, Ld, m, forms);
      diffuse += (cosineSampled.diffuse + cosineSampled.sheen) * kPi;
      if (m.clearcoat > 0.0) coat += ggxSample(coatAlpha, u, (j + 0.5) / samples).coat;
    }
  }
  return (specular + diffuse + dvec3(coat)) / (double(samples) * samples);
}

AlbedoTable::AlbedoTable(const ReferenceMaterial& m, const BrdfForms& forms, int bins, int samples) {
  for (int b = 0; b < bins; ++b) values_.push_back(directionalAlbedo(m, (b + 0.5) / bins, forms, samples));
}

dvec3 AlbedoTable::operator()(double NoV) const {
  const int bins = int(values_.size());
  const double x = std::clamp(NoV * bins - 0.5, 0.0, bins - 1.0);
  const int i = std::min(int(x), bins - 2);
  const double f = x - i;
  return values_[i] * (1.0 - f) + values_[i + 1] * f;
}

}  // namespace pbr::reference
