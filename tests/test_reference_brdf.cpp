#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "reference/brdf_form_names.hpp"
#include "reference/directional_albedo.hpp"
#include "core/scene/builtin_scenes.hpp"
#include "reference/reference_brdf.hpp"
#include "reference/reference_renderer.hpp"

using namespace pbr::reference;
using pbr::Diffuse;
using pbr::Fresnel;
using pbr::Visibility;

TEST_CASE("reference: exact dielectric Fresnel has its textbook values") {
  // Normal incidence: ((eta - 1) / (eta + 1))^2; grazing incidence: 1.
  CHECK(fresnelDielectric(1.0, 1.5) == doctest::Approx(0.04).epsilon(1e-12));
  CHECK(fresnelDielectric(0.0, 1.5) == doctest::Approx(1.0).epsilon(1e-12));
  CHECK(iorFromF0(0.04) == doctest::Approx(1.5).epsilon(1e-12));
  // Brewster's angle, tan(theta_B) = eta: p-polarised light is not reflected, so the unpolarised reflectance
  // is half the s-polarised one, ((cos i - eta cos t) / (cos i + eta cos t))^2 / 2.
  const double ci = std::cos(std::atan(1.5)), ct = std::sqrt(1.0 - (1.0 - ci * ci) / (1.5 * 1.5));
  const double rs = std::pow((ci - 1.5 * ct) / (ci + 1.5 * ct), 2.0);
  CHECK(fresnelDielectric(ci, 1.5) == doctest::Approx(rs / 2.0).epsilon(1e-9));
}

TEST_CASE("reference: directional albedo of the reference BRDF stays within [0, 1] and matches Lambert") {
  for (double roughness : {0.05, 0.3, 0.6, 1.0}) {
    for (double nv : {0.05, 0.3, 0.7, 1.0}) {
      for (double metal : {0.0, 1.0}) {
        const dvec3 a = directionalAlbedo({dvec3(1.0), roughness, metal}, nv);
        CAPTURE(roughness);
        CAPTURE(nv);
        CAPTURE(metal);
        CHECK(a.x <= 1.005);
        CHECK(a.x > 0.2);
      }
    }
  }
  // A black dielectric reflects only its specular lobe: about F0 = 0.04 at normal incidence for a smooth one.
  CHECK(directionalAlbedo({dvec3(0.0), 0.05, 0.0}, 1.0).x == doctest::Approx(0.04).epsilon(0.05));
  // GGX's visibility term stays finite and symmetric.
  CHECK(smithVisibilityExact(0.3, 0.7, 0.2) == doctest::Approx(smithVisibilityExact(0.7, 0.3, 0.2)));
}

TEST_CASE("reference: scenes it cannot render exactly are refused, not approximated") {
  pbr::Scene withEnvironment = pbr::makeBuiltinScene("sphere-grid");
  withEnvironment.environment = pbr::EnvironmentDesc{};
  CHECK_THROWS_AS(renderReference(withEnvironment, 8, 8), pbr::SceneError);
  // A mesh has no exact shape to ray-cast: analytic geometry refuses it, mesh geometry renders its triangles.
  pbr::Scene withMesh = pbr::makeBuiltinScene("sphere-grid");
  withMesh.objects[24].shape = pbr::Shape::Mesh;  // the centre sphere
  ReferenceOptions analytic;
  analytic.geometry = Geometry::Analytic;
  CHECK_THROWS_AS(renderReference(withMesh, 8, 8, analytic), pbr::SceneError);
  const ReferenceFrame meshes = renderReference(withMesh, 9, 9);  // the centre pixel sees the centre sphere
  CHECK(meshes.objectIds[4 * 9 + 4] == 24);
  CHECK(meshes.radiance.at(4, 4)[0] > 0.0f);
}

TEST_CASE("reference: the study forms evaluate the study's GGX, Hammon, Schlick, (1 - F(v.h)) model") {
  // The study's model written out from its papers, apart from evaluateBrdf's assembly of its terms.
  const auto studyModel = [](const dvec3& N, const dvec3& V, const dvec3& L, const ReferenceMaterial& m) {
    const dvec3 H = glm::normalize(V + L);
    const double nh = glm::dot(N, H), nv = glm::dot(N, V), nl = glm::dot(N, L), vh = glm::dot(V, H);
    const double a = m.roughness * m.roughness, a2 = a * a;
    // Walter et al. 2007, eq. 33: D = a^2 / (pi cos^4 theta_h (a^2 + tan^2 theta_h)^2).
    const double c2 = nh * nh, k = a2 + (1.0 - c2) / c2;
    const double d = a2 / (kPi * c2 * c2 * k * k);
    // Hammon 2017: V = 0.5 / mix(2 n.l n.v, n.l + n.v, a).
    const double vis = 0.5 / ((1.0 - a) * (2.0 * nl * nv) + a * (nl + nv));
    // Schlick 1994 with F0 = mix(0.04, baseColor, metalness).
    const dvec3 f0 = dvec3(0.04) * (1.0 - m.metalness) + m.baseColor * m.metalness;
    const dvec3 f = f0 + (dvec3(1.0) - f0) * std::pow(1.0 - vh, 5.0);
    return (dvec3(1.0) - f) * (1.0 - m.metalness) * m.baseColor / kPi + d * vis * f;
  };
  const BrdfForms study = BrdfForms::study();
  const dvec3 N(0.0, 0.0, 1.0);
  double worst = 0.0;
  for (double roughness : {0.1, 0.3, 0.6, 1.0}) {
    for (double metalness : {0.0, 0.5, 1.0}) {
      const ReferenceMaterial m{dvec3(0.9, 0.6, 0.3), roughness, metalness};
      for (double tv : {0.0, 0.4, 0.9, 1.3, 1.55}) {
        for (double tl : {0.1, 0.5, 1.0, 1.5}) {
          for (double pl : {0.0, 1.5, 3.14159}) {
            const dvec3 V(std::sin(tv), 0.0, std::cos(tv));
            const dvec3 L(std::sin(tl) * std::cos(pl), std::sin(tl) * std::sin(pl), std::cos(tl));
            const dvec3 f = evaluateBrdf(N, V, L, m, study).sum();
            const dvec3 expected = studyModel(N, V, L, m);
            for (int ch = 0; ch < 3; ++ch) worst = std::max(worst, std::abs(f[ch] - expected[ch]) / expected[ch]);
          }
        }
      }
    }
  }
  // Both sides are double precision: only the order of operations differs.
  CHECK(worst < 1e-12);
}

TEST_CASE("reference: each BRDF form has its closed form") {
  // Karis's fit is exactly 1 at grazing incidence and leaves 2^-12.53789 of (1 - F0) at normal incidence.
  CHECK(fresnelSchlickSG(0.0, 0.04) == 1.0);
  CHECK(fresnelSchlickSG(1.0, 0.04) == doctest::Approx(0.04 + 0.96 * std::exp2(-12.53789)).epsilon(1e-12));
  CHECK(fresnelSchlick(0.5, 0.04) == doctest::Approx(0.04 + 0.96 / 32.0).epsilon(1e-12));
  for (double nv : {0.05, 0.4, 1.0}) {
    for (double nl : {0.1, 0.7}) {
      CAPTURE(nv);
      CAPTURE(nl);
      // Hammon's fit runs from the smooth limit 1 / (4 n.l n.v) to 1 / (2 (n.l + n.v)) at alpha = 1.
      CHECK(smithVisibilityHammon(nv, nl, 0.0) == doctest::Approx(1.0 / (4.0 * nl * nv)).epsilon(1e-12));
      CHECK(smithVisibilityHammon(nv, nl, 1.0) == doctest::Approx(1.0 / (2.0 * (nl + nv))).epsilon(1e-12));
      // Walter et al. 2007, eq. 34: G1 = 2 n.x / (n.x + sqrt(a^2 + (1 - a^2) (n.x)^2)), uncorrelated.
      // Heitz 2014, "Understanding the Masking-Shadowing Function": height-correlated G2 =
      // 1 / (1 + Lambda(v) + Lambda(l)) with Lambda(x) = (sqrt(1 + a^2 tan^2 x) - 1) / 2.
      for (double a : {0.01, 0.3, 1.0}) {
        auto g1 = [a](double c) { return 2.0 * c / (c + std::sqrt(a * a + (1.0 - a * a) * c * c)); };
        CHECK(smithVisibilitySeparable(nv, nl, a) == doctest::Approx(g1(nv) * g1(nl) / (4.0 * nl * nv)).epsilon(1e-12));
        auto lambda = [a](double c) { return 0.5 * (std::sqrt(1.0 + a * a * (1.0 - c * c) / (c * c)) - 1.0); };
        const double g2 = 1.0 / (1.0 + lambda(nv) + lambda(nl));
        CHECK(smithVisibilityExact(nv, nl, a) == doctest::Approx(g2 / (4.0 * nl * nv)).epsilon(1e-12));
      }
    }
  }

  // Through evaluateBrdf: the forms change only their own term.
  const dvec3 N(0, 0, 1), V(std::sin(1.2), 0.0, std::cos(1.2)), L(-std::sin(0.3), 0.2, std::cos(0.3));
  const dvec3 Ln = glm::normalize(L), H = glm::normalize(V + Ln);
  const double vh = glm::dot(V, H);
  const ReferenceMaterial m{dvec3(0.9, 0.6, 0.3), 0.4, 0.3};
  BrdfForms schlick, sg, vhDiffuse;
  schlick.fresnel = Fresnel::Schlick;
  sg.fresnel = Fresnel::SchlickSG;
  vhDiffuse.fresnel = Fresnel::Schlick;
  vhDiffuse.diffuse = Diffuse::LambertOneMinusFVh;
  const BrdfLobes fs = evaluateBrdf(N, V, Ln, m, schlick), fsg = evaluateBrdf(N, V, Ln, m, sg);
  const BrdfLobes fvh = evaluateBrdf(N, V, Ln, m, vhDiffuse);
  for (int ch = 0; ch < 3; ++ch) {
    const double f0 = 0.04 * (1.0 - m.metalness) + m.baseColor[ch] * m.metalness;
    const double fSchlick = f0 + (1.0 - f0) * std::pow(1.0 - vh, 5.0);
    const double fSG = f0 + (1.0 - f0) * std::exp2((-5.55473 * vh - 6.98316) * vh);
    CHECK(fsg.specular[ch] / fs.specular[ch] == doctest::Approx(fSG / fSchlick).epsilon(1e-12));
    CHECK(fvh.specular[ch] == doctest::Approx(fs.specular[ch]).epsilon(1e-12));
    const double lambert = (1.0 - m.metalness) * m.baseColor[ch] / 3.14159265358979323846;
    CHECK(fvh.diffuse[ch] == doctest::Approx((1.0 - fSchlick) * lambert).epsilon(1e-12));
  }
}

TEST_CASE("reference: white furnace, Lambert weighted by (1 - F(v.h)) reflects up to 1.84 at grazing views") {
  // A white dielectric seen at n.v = 0.01 (89.4 degrees), where the specular lobe takes most of the light. With
  // the diffuse weight 1 - F(v.h) the diffuse lobe barely notices (v.h stays far from 0 for most l), so the two
  // lobes add up to more than 1; with 1 - F(n.v) the diffuse lobe gives way and the sum stays at most 1. The
  // other terms are the renderer's standard ones (exact height-correlated Smith, Schlick), as in its
  // lambert-1-f-vh variant.
  constexpr double kGrazing = 0.01;
  constexpr int kSamples = 256;  // per axis: the albedo moves by < 1e-3 from 256 to 512
  BrdfForms vh, standard;
  vh.fresnel = standard.fresnel = Fresnel::Schlick;
  vh.diffuse = Diffuse::LambertOneMinusFVh;
  double worstVh = 0.0, worstRoughness = 0.0, worstStandard = 0.0;
  for (double roughness : {0.05, 0.1, 0.2, 0.3, 0.5, 1.0}) {
    const ReferenceMaterial white{dvec3(1.0), roughness, 0.0};
    const double gain = directionalAlbedo(white, kGrazing, vh, kSamples).x;
    const double kept = directionalAlbedo(white, kGrazing, standard, kSamples).x;
    MESSAGE("roughness " << roughness << ": albedo at n.v = " << kGrazing << " with (1 - F(v.h)) " << gain
                         << ", with (1 - F(n.v)) " << kept);
    if (gain > worstVh) worstVh = gain, worstRoughness = roughness;
    worstStandard = std::max(worstStandard, kept);
    // Every roughness gains over the (1 - F(n.v)) form; the roughest least (the specular lobe is weakest there).
    CAPTURE(roughness);
    CHECK(gain > kept);
    CHECK(gain > 1.0);
  }
  // Measured: 1.842 at roughness 0.05 (1.71 at 0.1, 1.01 at 1.0); the band is 20x the quadrature's change.
  MESSAGE("largest albedo with (1 - F(v.h)): " << worstVh << " at roughness " << worstRoughness);
  CHECK(worstVh > 1.82);
  CHECK(worstVh < 1.86);
  CHECK(worstRoughness == 0.05);
  // The directional albedo test above allows the same 0.5% for the quadrature.
  CHECK(worstStandard <= 1.005);
}

TEST_CASE("reference: parseBrdfForms reads study or key=value forms, and toString writes every key") {
  CHECK(toString(parseBrdfForms("")) == "visibility=exact,ndf=ggx,fresnel=exact,diffuse=lambert-1-f");
  CHECK(toString(parseBrdfForms("study")) == "visibility=hammon,ndf=ggx,fresnel=schlick,diffuse=lambert-1-f-vh");
  const BrdfForms f = parseBrdfForms("vis=separable,ndf=ggx,fresnel=schlick-sg,diffuse=lambert");
  CHECK((f.visibility == Visibility::Separable));
  CHECK((f.fresnel == Fresnel::SchlickSG));
  CHECK((f.diffuse == Diffuse::Lambert));
  CHECK(toString(parseBrdfForms(toString(f))) == toString(f));
  // Forms the reference does not have, and study with other keys.
  for (const char* bad : {"study,fresnel=exact", "ndf=beckmann", "diffuse=burley", "fresnel", "specular=ggx"}) {
    CAPTURE(bad);
    CHECK_THROWS_AS(parseBrdfForms(bad), std::invalid_argument);
  }
}

TEST_CASE("reference: its forms are the renderer's vocabulary, its defaults the renderer's but for exact Fresnel") {
  const pbr::ShadingVariant renderer;
  const BrdfForms reference;
  // The one stated difference: the yardstick evaluates the exact dielectric Fresnel the renderer approximates.
  CHECK((renderer.fresnel == Fresnel::Schlick));
  CHECK((reference.fresnel == Fresnel::Exact));
  CHECK((reference.visibility == renderer.visibility));
  CHECK((reference.ndf == renderer.ndf));
  CHECK((reference.diffuse == renderer.diffuse));
  // A variant's forms carry over term for term; the terms the reference cannot evaluate are named.
  const pbr::ShadingVariant study = pbr::parseShadingVariant("study");
  CHECK(toString(BrdfForms(study)) == pbr::toString(study));
  CHECK_THROWS_WITH_AS(BrdfForms(pbr::parseShadingVariant("ndf=beckmann")),
                       "the reference cannot evaluate ndf=beckmann (it has GGX alone)", std::invalid_argument);
  CHECK_THROWS_WITH_AS(parseBrdfForms("diffuse=burley"),
                       "the reference cannot evaluate diffuse=burley (lambert-1-f, lambert-1-f-vh, lambert)",
                       std::invalid_argument);
  CHECK_THROWS_AS(parseBrdfForms("lobe=sg"), std::invalid_argument);
}

TEST_CASE("reference: KHR_materials_ior and _specular, from the specifications' formulas") {
  using namespace pbr::reference;
  const ReferenceMaterial core;
  // ior 1.5 is the core material's F0, exactly.
  CHECK(dielectricF0(core) == dvec3(0.04));
  ReferenceMaterial m;
  m.baseColor = dvec3(0.5);
  m.roughness = 0.4;
  const dvec3 N(0, 0, 1), V = glm::normalize(dvec3(0.3, 0, 1)), L = glm::normalize(dvec3(-0.5, 0.2, 1));
  // specular 0: no specular lobe, and the diffuse lobe is Lambert's, nothing taken by Fresnel.
  m.specular = 0.0;
  for (const Fresnel f : {Fresnel::Exact, Fresnel::Schlick, Fresnel::SchlickSG}) {
    BrdfForms forms;
    forms.fresnel = f;
    const BrdfLobes lobes = evaluateBrdf(N, V, L, m, forms);
    CHECK(lobes.specular == dvec3(0.0));
    CHECK(lobes.diffuse.x == doctest::Approx(0.5 / kPi).epsilon(1e-15));
  }
  // At normal incidence Schlick's and the exact Fresnel term give F0 = ((ior - 1) / (ior + 1))^2 colour strength:
  // the specular lobe over D V is F(1) when H = N = V = L.
  m.specular = 0.5;
  m.ior = 2.0;
  m.specularColor = dvec3(2.0, 1.0, 0.25);
  const double f0 = 1.0 / 9.0;
  const dvec3 expected = glm::min(f0 * m.specularColor, dvec3(1.0)) * 0.5;
  for (const Fresnel f : {Fresnel::Exact, Fresnel::Schlick}) {
    BrdfForms forms;
    forms.fresnel = f;
    const BrdfLobes lobes = evaluateBrdf(N, N, N, m, forms);
    const double alpha = alphaFromRoughness(m.roughness);
    const double dv = ggxD(1.0, alpha) * smithVisibilityExact(1.0, 1.0, alpha);
    for (int i = 0; i < 3; ++i) CHECK(lobes.specular[i] / dv == doctest::Approx(expected[i]).epsilon(1e-12));
    // glTF's fresnel_mix: the base weighted by 1 - max_value(F).
    const double largest = std::max({expected.x, expected.y, expected.z});
    CHECK(lobes.diffuse.x == doctest::Approx((1.0 - largest) * 0.5 / kPi).epsilon(1e-12));
  }
}

TEST_CASE("reference: a clear coat over a white base conserves energy (white furnace)") {
  using namespace pbr::reference;
  // fresnel_coat weights the base by 1 - clearcoat Fc and adds the coat's lobe by clearcoat Fc: with the coat's
  // lobe reflecting at most all it receives, the layered albedo stays <= 1 at every angle and roughness.
  for (const double roughness : {0.05, 0.3, 0.7, 1.0}) {
    for (const double coatRoughness : {0.0, 0.2, 0.6}) {
      ReferenceMaterial m;
      m.baseColor = dvec3(1.0);
      m.roughness = roughness;
      m.clearcoat = 1.0;
      m.clearcoatRoughness = coatRoughness;
      for (const double NoV : {0.02, 0.2, 0.5, 0.9, 1.0}) {
        CAPTURE(roughness);
        CAPTURE(coatRoughness);
        CAPTURE(NoV);
        const dvec3 albedo = directionalAlbedo(m, NoV, BrdfForms(), 64);
        CHECK(albedo.x <= 1.0 + 1e-3);
        ReferenceMaterial bare = m;
        bare.clearcoat = 0.0;
        // The coat adds reflection where the base would lose it to Fresnel, never less than (1 - Fc) of the base.
        CHECK(albedo.x >= (1.0 - fresnelSchlick(NoV, 0.04)) * directionalAlbedo(bare, NoV, BrdfForms(), 64).x - 1e-3);
      }
    }
  }
}

TEST_CASE("reference: the sheen's albedo scaling keeps a white sheen over a white base under the white furnace's 1") {
  using namespace pbr::reference;
  for (const double sheenRoughness : {0.07, 0.3, 0.6, 1.0}) {
    for (const double NoV : {0.05, 0.3, 0.7, 1.0}) {
      CAPTURE(sheenRoughness);
      CAPTURE(NoV);
      const double e = sheenAlbedo(NoV, sheenRoughness);
      CHECK(e > 0.0);
      CHECK(e <= 1.0);
      ReferenceMaterial m;
      m.baseColor = dvec3(1.0);
      m.roughness = 0.5;
      m.sheenColor = dvec3(1.0);
      m.sheenRoughness = sheenRoughness;
      // The sheen adds E, and scales the base (at most 1) by 1 - E: together at most 1.
      CHECK(directionalAlbedo(m, NoV, BrdfForms(), 64).x <= 1.0 + 2e-3);
    }
  }
}

TEST_CASE("reference: a white transmissive surface reflects and transmits at most what it receives (white furnace)") {
  using namespace pbr::reference;
  // fresnel_mix over mix(diffuse, specular_btdf, transmission): the reflected albedo (the BRDF's, its diffuse lobe
  // weighted by 1 - transmission) plus the transmitted share (the BTDF integrated over the microfacet normals, or
  // the smooth surface's delta lobe) stays <= 1; smooth and fully transmissive it is all but masking's loss.
  const dvec3 N(0.0, 0.0, 1.0);
  for (const double transmission : {0.5, 1.0}) {
    for (const double roughness : {0.0, 0.3, 0.7}) {
      for (const double NoV : {0.1, 0.5, 0.9, 1.0}) {
        CAPTURE(transmission);
        CAPTURE(roughness);
        CAPTURE(NoV);
        ReferenceMaterial m;
        m.baseColor = dvec3(1.0);
        m.roughness = roughness;
        m.transmission = transmission;
        const dvec3 V(std::sqrt(1.0 - NoV * NoV), 0.0, NoV);
        const double reflected = directionalAlbedo(m, NoV, BrdfForms(), 64).x;
        double transmitted = 0.0;
        if (roughness <= kMinRoughness) {
          transmitted = smoothTransmittance(N, V, m).x;
        } else {
          // GGX's normals in proportion to D(h) n.h over a 128 x 128 grid of strata.
          const int n = 128;
          const double alpha = alphaFromRoughness(roughness);
          for (int i = 0; i < n; ++i) {
            for (int j = 0; j < n; ++j) {
              const double u1 = (i + 0.5) / n, phi = 2.0 * kPi * (j + 0.5) / n;
              const double c = std::sqrt((1.0 - u1) / (1.0 + (alpha * alpha - 1.0) * u1));
              const double s = std::sqrt(1.0 - c * c);
              dvec3 L;
              transmitted += sampledTransmittance(N, V, {s * std::cos(phi), s * std::sin(phi), c}, m, {}, L).x;
            }
          }
          transmitted /= double(n * n);
        }
        CHECK(transmitted > 0.0);
        CHECK(reflected + transmitted <= 1.0 + 2e-3);
        if (roughness <= kMinRoughness && transmission == 1.0 && NoV >= 0.5) {
          CHECK(reflected + transmitted >= 0.98);
        }
      }
    }
  }
}
