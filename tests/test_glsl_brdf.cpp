// GPU unit tests of the lighting GLSL (shaders/lighting/brdf.glsl, lights.glsl) against mathematical
// references: each expected value is derived independently of the shader code.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "core/scene/shading_model.hpp"
#include "reference/reference_brdf.hpp"
#include "tests/gl_test_context.hpp"
#include "tests/glsl_probe.hpp"

using pbr::test::GlslProbe;

namespace {

constexpr double kPi = 3.14159265358979323846;

double relativeError(double actual, double expected) { return std::abs(actual - expected) / std::abs(expected); }

// Midpoint nodes of theta in [0, pi/2] under theta = a sinh(t S): steps grow from S a / n (hundredths of `a`)
// at the pole to about S pi/2 / n at the horizon, so one grid resolves a GGX peak of width `a` and the
// smooth remainder of the hemisphere alike.
struct ThetaNode {
  double theta;
  double weight;  // d theta
};

std::vector<ThetaNode> thetaGrid(double a, int n) {
  const double s = std::asinh(kPi / 2.0 / a);
  std::vector<ThetaNode> nodes;
  for (int i = 0; i < n; ++i) {
    const double t = (i + 0.5) / n;
    nodes.push_back({a * std::sinh(t * s), a * s * std::cosh(t * s) / n});
  }
  return nodes;
}

// Fresnel probes: for each row of F0s, v.h from 0 to 1 in kSteps steps, as (v.h, F0).
constexpr int kSteps = 256;
const std::vector<glm::vec3> kFresnelF0s = {{0.0f, 0.04f, 0.5f}, {0.9f, 0.97f, 1.0f}};
std::vector<glm::vec4> fresnelInputs() {
  std::vector<glm::vec4> input;
  for (const glm::vec3& f0 : kFresnelF0s)
    for (int i = 0; i <= kSteps; ++i) input.emplace_back(static_cast<float>(i) / kSteps, f0);
  return input;
}

}  // namespace

TEST_CASE("glsl brdf: D_GGX is normalised, integral of D(n.h) n.h over the hemisphere is 1") {
  PBR_REQUIRE_GL();
  const GlslProbe probe("ggx normalisation", R"(
#include "lighting/brdf.glsl"
vec4 probe(vec4 v) { return vec4(D_GGX(v.x, v.z, v.y)); }
)");
  constexpr int kNodes = 512;
  std::vector<double> roughness;
  for (int i = 1; i <= 10; ++i) roughness.push_back(0.1 * i);

  std::vector<glm::vec4> input;
  for (double r : roughness) {
    for (const ThetaNode& node : thetaGrid(r * r, kNodes)) {
      const double sinTheta = std::sin(node.theta);
      input.emplace_back(static_cast<float>(std::cos(node.theta)), static_cast<float>(r * r),
                         static_cast<float>(sinTheta * sinTheta), 0.0f);
    }
  }
  const std::vector<glm::vec4> d = probe.run(input);

  for (size_t k = 0; k < roughness.size(); ++k) {
    const double a = roughness[k] * roughness[k];
    double gpu = 0.0, reference = 0.0;
    const std::vector<ThetaNode> grid = thetaGrid(a, kNodes);
    for (size_t i = 0; i < grid.size(); ++i) {
      const double c = std::cos(grid[i].theta);
      const double w = 2.0 * kPi * c * std::sin(grid[i].theta) * grid[i].weight;
      gpu += w * d[k * kNodes + i].x;
      reference += w * pbr::reference::ggxD(c, a);
    }
    CAPTURE(roughness[k]);
    INFO("the quadrature alone must be exact to 1e-4 for the 1% tolerance to test the shader");
    CHECK(std::abs(reference - 1.0) < 1e-4);
    INFO("GPU integral of D_GGX(n.h) n.h = " << gpu);
    CHECK(std::abs(gpu - 1.0) < 0.01);
  }
}

TEST_CASE("glsl brdf: Smith visibility is symmetric and matches the height-correlated closed form") {
  PBR_REQUIRE_GL();
  const GlslProbe probe("smith visibility", R"(
#include "lighting/brdf.glsl"
vec4 probe(vec4 v) {
  return vec4(V_SmithGGXCorrelated(v.x, v.y, v.z), V_SmithGGXCorrelated(v.y, v.x, v.z),
              V_SmithGGXCorrelatedFast(v.x, v.y, v.z), V_SmithGGXCorrelatedFast(v.y, v.x, v.z));
}
)");
  const std::vector<double> cosines = {0.01, 0.05, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 0.99, 1.0};
  const std::vector<double> alphas = {0.0025, 0.01, 0.09, 0.25, 0.5625, 1.0};
  std::vector<glm::vec4> input;
  for (double a : alphas)
    for (double noV : cosines)
      for (double noL : cosines) input.emplace_back(noV, noL, a, 0.0);
  const std::vector<glm::vec4> v = probe.run(input);

  for (size_t i = 0; i < input.size(); ++i) {
    const double noV = input[i].x, noL = input[i].y, a = input[i].z;
    CAPTURE(noV);
    CAPTURE(noL);
    CAPTURE(a);
    // Swapping the arguments only reorders commutative float operations: a few ulps at most.
    CHECK(relativeError(v[i].y, v[i].x) < 1e-6);
    CHECK(relativeError(v[i].w, v[i].z) < 1e-6);
    const double a2 = a * a;
    const double closedForm =
        0.5 / (noL * std::sqrt(noV * noV * (1.0 - a2) + a2) + noV * std::sqrt(noL * noL * (1.0 - a2) + a2));
    INFO("V_SmithGGXCorrelated = " << v[i].x << ", closed form " << closedForm);
    CHECK(relativeError(v[i].x, closedForm) < 1e-5);
  }
}

TEST_CASE("glsl brdf: white furnace, directional albedo of brdfCookTorrance is at most 1") {
  PBR_REQUIRE_GL();
  // The integral over L runs over half vectors: dL = 4 (v.h) dH maps the upper hemisphere of H with v.h > 0
  // onto the sphere of L, and a GGX lobe of width `a` is isotropic around n in H, so the sinh grid in
  // theta_h resolves it down to roughness 0.05 (a = 0.0025), where the lobe is far too thin for any
  // uniform grid in L. The integrand is even in phi (v lies in the xz plane), hence phi in [0, pi], doubled.
  constexpr int kTheta = 256, kPhi = 128;
  // The same grid integrates a Lambertian to 1 within 2e-4 at every roughness and view (checked below), so a
  // bound of 1.01 is 50x the quadrature error: an excess over it is the shader's.
  constexpr double kMaxAlbedo = 1.01;
  const std::vector<double> roughnesses = {0.05, 0.1, 0.2, 0.35, 0.5, 0.75, 1.0};
  const std::vector<double> views = {0.05, 0.1, 0.25, 0.5, 0.75, 1.0};
  const char* source = R"(
#include "lighting/brdf.glsl"
// v = (theta_h, phi_h, n.v, roughness); n = +z and v in the xz plane.
vec4 probe(vec4 v) {
  vec3 N = vec3(0.0, 0.0, 1.0);
  vec3 V = vec3(sqrt(1.0 - v.z * v.z), 0.0, v.z);
  vec3 H = vec3(sin(v.x) * cos(v.y), sin(v.x) * sin(v.y), cos(v.x));
  vec3 L = reflect(-V, H);
  return vec4(brdfCookTorrance(N, V, L, v.z, vec3(1.0), v.w, METALNESS), 0.0);
}
)";

  for (const std::string metalness : {"0.0", "1.0"}) {
    const GlslProbe probe("white furnace", source, {{"METALNESS", metalness}});
    std::vector<glm::vec4> input;
    std::vector<double> weights;      // quadrature weight times n.l times the Jacobian 4 (v.h)
    std::vector<size_t> configStart;  // first sample of each (roughness, view) pair
    for (double roughness : roughnesses) {
      // MIN_ROUGHNESS (0.045) is below every roughness here, so a = roughness^2.
      const std::vector<ThetaNode> grid = thetaGrid(roughness * roughness, kTheta);
      for (double noV : views) {
        configStart.push_back(input.size());
        const double vx = std::sqrt(1.0 - noV * noV);
        for (const ThetaNode& node : grid) {
          for (int j = 0; j < kPhi; ++j) {
            const double phi = (j + 0.5) * kPi / kPhi;
            const double hx = std::sin(node.theta) * std::cos(phi), hz = std::cos(node.theta);
            const double voH = vx * hx + noV * hz;
            const double noL = 2.0 * voH * hz - noV;
            if (voH <= 0.0 || noL <= 0.0) continue;
            input.emplace_back(node.theta, phi, noV, roughness);
            weights.push_back(std::sin(node.theta) * node.weight * 2.0 * kPi / kPhi * noL * 4.0 * voH);
          }
        }
      }
    }
    configStart.push_back(input.size());
    const std::vector<glm::vec4> f = probe.run(input);

    for (size_t c = 0; c + 1 < configStart.size(); ++c) {
      const double roughness = roughnesses[c / views.size()], noV = views[c % views.size()];
      double albedo = 0.0, lambert = 0.0;
      for (size_t i = configStart[c]; i < configStart[c + 1]; ++i) {
        albedo += weights[i] * std::max({f[i].x, f[i].y, f[i].z});
        lambert += weights[i] / kPi;
      }
      CAPTURE(metalness);
      CAPTURE(roughness);
      CAPTURE(noV);
      INFO("quadrature check: a Lambertian integrates to " << lambert);
      REQUIRE(std::abs(lambert - 1.0) < 2e-4);
      INFO("directional albedo = " << albedo);
      CHECK(albedo <= kMaxAlbedo);
      // A rough white dielectric is mostly Lambertian: a broken diffuse term cannot hide behind the bound.
      if (metalness == "0.0" && roughness == 1.0 && noV >= 0.5) CHECK(albedo > 0.5);
    }
  }
}

TEST_CASE("glsl brdf: F_Schlick is F0 + (1 - F0)(1 - v.h)^5: F0 at v.h = 1, 1 at v.h = 0, decreasing") {
  PBR_REQUIRE_GL();
  const GlslProbe probe("schlick", R"(
#include "lighting/brdf.glsl"
vec4 probe(vec4 v) { return vec4(F_Schlick(v.yzw, v.x), 0.0); }
)");
  const std::vector<glm::vec3>& f0s = kFresnelF0s;
  const std::vector<glm::vec4> f = probe.run(fresnelInputs());

  for (size_t s = 0; s < f0s.size(); ++s) {
    const glm::vec4* row = &f[s * (kSteps + 1)];
    for (int ch = 0; ch < 3; ++ch) {
      const float f0 = f0s[s][ch];
      CAPTURE(f0);
      CHECK(row[0][ch] == doctest::Approx(1.0).epsilon(1e-6));
      CHECK(row[kSteps][ch] == doctest::Approx(f0).epsilon(1e-6));
      for (int i = 0; i < kSteps; ++i) {
        const double voH = static_cast<double>(i) / kSteps;
        CAPTURE(voH);
        CHECK(std::abs(row[i][ch] - (f0 + (1.0 - f0) * std::pow(1.0 - voH, 5.0))) < 1e-6);
        CHECK(row[i + 1][ch] <= row[i][ch]);
        // Below v.h = 0.5 each step lowers F by at least 0.3 (1 - F0) / kSteps, far above float resolution.
        if (f0 < 1.0f && voH < 0.5) CHECK(row[i + 1][ch] < row[i][ch]);
      }
    }
  }
}

TEST_CASE("glsl brdf: F_SchlickSG is F0 + (1 - F0) 2^((-5.55473 c - 6.98316) c), Karis's fit of Schlick") {
  PBR_REQUIRE_GL();
  const GlslProbe probe("schlick sg", R"(
#include "lighting/brdf.glsl"
vec4 probe(vec4 v) { return vec4(F_SchlickSG(v.yzw, v.x), 0.0); }
)");
  const std::vector<glm::vec3>& f0s = kFresnelF0s;
  const std::vector<glm::vec4> f = probe.run(fresnelInputs());

  double worstAgainstPow5 = 0.0;
  for (size_t s = 0; s < f0s.size(); ++s) {
    for (int ch = 0; ch < 3; ++ch) {
      const double f0 = f0s[s][ch];
      CAPTURE(f0);
      for (int i = 0; i <= kSteps; ++i) {
        const double c = static_cast<double>(i) / kSteps;
        const double expected = f0 + (1.0 - f0) * std::exp2((-5.55473 * c - 6.98316) * c);
        CAPTURE(c);
        // GLSL 4.50 allows exp2 3 + 2|x| ulp; |x| <= 12.6 here, so 28 ulp of a value <= 1: 2e-6.
        CHECK(std::abs(f[s * (kSteps + 1) + i][ch] - expected) < 2e-6);
        worstAgainstPow5 = std::max(worstAgainstPow5, std::abs(expected - (f0 + (1.0 - f0) * std::pow(1.0 - c, 5.0))));
      }
    }
  }
  // The fit is close to Schlick's power but not equal to it: a variant of its own, not a renamed Schlick.
  MESSAGE("spherical-Gaussian Fresnel: largest difference from (1 - c)^5 " << worstAgainstPow5);
  CHECK(worstAgainstPow5 > 1e-3);
  CHECK(worstAgainstPow5 < 1e-2);
}

TEST_CASE("glsl brdf: the diffuse weight is (1 - F(n.v)) by default and (1 - F(v.h)) under DIFFUSE_LAMBERT_1_F_VH") {
  PBR_REQUIRE_GL();
  // v = (n.v, v.h, metalness, n.l); Schlick Fresnel, the standard model's.
  const char* source = R"(
#include "lighting/brdf.glsl"
vec4 probe(vec4 v) { return vec4(diffuseLobe(vec3(0.9, 0.6, 0.3), v.z, 0.5, v.x, v.w, v.y), 0.0); }
)";
  const glm::dvec3 baseColor(0.9f, 0.6f, 0.3f);
  std::vector<glm::vec4> input;
  for (double noV : {0.01, 0.2, 0.5, 0.9, 1.0})
    for (double voH : {0.0, 0.1, 0.3, 0.6, 0.95, 1.0})
      for (double metalness : {0.0, 0.3, 1.0}) input.emplace_back(noV, voH, metalness, 0.7);

  for (const bool vh : {false, true}) {
    pbr::ShadingVariant variant;
    if (vh) variant.diffuse = pbr::Diffuse::LambertOneMinusFVh;
    const GlslProbe probe("diffuse weight", source, pbr::shaderDefines(variant));
    const std::vector<glm::vec4> fd = probe.run(input);
    for (size_t i = 0; i < input.size(); ++i) {
      const double noV = input[i].x, voH = input[i].y, metalness = input[i].z;
      const double c = vh ? voH : noV;
      CAPTURE(vh);
      CAPTURE(noV);
      CAPTURE(voH);
      CAPTURE(metalness);
      for (int ch = 0; ch < 3; ++ch) {
        const double f0 = 0.04 * (1.0 - metalness) + baseColor[ch] * metalness;
        const double f = f0 + (1.0 - f0) * std::pow(1.0 - c, 5.0);
        const double expected = (1.0 - f) * (1.0 - metalness) * baseColor[ch] / kPi;
        // A few float roundings of values below 1 / pi.
        CHECK(std::abs(fd[i][ch] - expected) < 1e-6);
      }
    }
  }
}

TEST_CASE("glsl brdf: brdfCookTorrance under the study defines is the study's GGX, Hammon, Schlick, (1 - F(v.h)) model") {
  PBR_REQUIRE_GL();
  // v = (theta_v, theta_l, phi_l, roughness); n = +z, v in the xz plane.
  const char* source = R"(
#include "lighting/brdf.glsl"
vec4 probe(vec4 v) {
  vec3 N = vec3(0.0, 0.0, 1.0);
  vec3 V = vec3(sin(v.x), 0.0, cos(v.x));
  vec3 L = vec3(sin(v.y) * cos(v.z), sin(v.y) * sin(v.z), cos(v.y));
  return vec4(brdfCookTorrance(N, V, L, dot(N, V), vec3(0.9, 0.6, 0.3), v.w, METALNESS), 0.0);
}
)";
  const glm::dvec3 baseColor(0.9f, 0.6f, 0.3f);
  // Float against double: a few ulps per operation, amplified near the GGX peak at roughness 0.1, where D depends
  // on 1 + (n.h)^2 (a^2 - 1) ~ a^2 = 1e-4. Measured at most 2.5e-6 on llvmpipe; 2e-5 leaves 8x for other drivers.
  constexpr double kStudyTolerance = 2e-5;
  constexpr double kDeg = kPi / 180.0;
  std::vector<glm::vec4> input;
  for (double roughness : {0.1, 0.25, 0.5, 0.75, 1.0})
    for (double thetaV : {0.0, 20.0, 45.0, 70.0, 85.0})
      for (double thetaL : {0.0, 20.0, 45.0, 70.0, 85.0})
        for (double phiL : {0.0, 60.0, 120.0, 180.0}) input.emplace_back(thetaV * kDeg, thetaL * kDeg, phiL * kDeg, roughness);

  double worst = 0.0;
  for (const char* metalness : {"0.0", "0.5", "1.0"}) {
    pbr::ShaderDefines defines = pbr::shaderDefines(pbr::parseShadingVariant("study"));
    defines.push_back({"METALNESS", metalness});
    const GlslProbe probe("study brdf", source, defines);
    const std::vector<glm::vec4> f = probe.run(input);
    for (size_t i = 0; i < input.size(); ++i) {
      // The same float angles the shader received, in double from here on.
      const double tv = input[i].x, tl = input[i].y, pl = input[i].z, roughness = input[i].w;
      const glm::dvec3 N(0.0, 0.0, 1.0), V(std::sin(tv), 0.0, std::cos(tv));
      const glm::dvec3 L(std::sin(tl) * std::cos(pl), std::sin(tl) * std::sin(pl), std::cos(tl));
      const pbr::reference::ReferenceMaterial m{baseColor, roughness, std::stod(metalness)};
      const glm::dvec3 expected = pbr::reference::evaluateBrdf(N, V, L, m, pbr::reference::BrdfForms::study()).sum();
      CAPTURE(metalness);
      CAPTURE(roughness);
      CAPTURE(tv);
      CAPTURE(tl);
      CAPTURE(pl);
      for (int ch = 0; ch < 3; ++ch) {
        const double error = relativeError(f[i][ch], expected[ch]);
        worst = std::max(worst, error);
        INFO("GLSL " << f[i][ch] << ", study model " << expected[ch]);
        CHECK(error < kStudyTolerance);
      }
    }
  }
  MESSAGE("study BRDF: largest relative difference of the GLSL from the double-precision study model " << worst);
}

TEST_CASE("glsl lights: distanceAttenuation is windowed inverse-square, at most 1, and 0 from R on") {
  PBR_REQUIRE_GL();
  const GlslProbe probe("distance attenuation", R"(
#include "lighting/lights.glsl"
vec4 probe(vec4 v) { return vec4(distanceAttenuation(v.x * v.x, v.y)); }  // it takes the squared distance
)");
  // Below R = 0.01 the 0.01 distance clamp shows through the window near R; above it only the limit of 1 does.
  const std::vector<double> radii = {0.005, 0.05, 0.5, 1.0, 10.0, 100.0};
  const std::vector<double> fractions = {0.0,  1e-4, 1e-3, 0.005, 0.01, 0.02, 0.05, 0.1, 0.2, 0.3, 0.5,
                                         0.7,  0.8,  0.9,  0.95,  0.99, 0.999, 1.0, 1.001, 1.5, 10.0};
  std::vector<glm::vec4> input;
  for (double r : radii)
    for (double x : fractions) input.emplace_back(x * r, r, 0.0, 0.0);
  // Distances below the 0.01 clamp, a light on the surface, and radii R <= 0, which reach nothing.
  for (double d : {0.0, 1e-6, 0.003, 0.0099}) input.emplace_back(d, 1.0, 0.0, 0.0);
  for (double d : {0.0, 0.5, 2.0}) input.emplace_back(d, 0.0, 0.0, 0.0);
  for (double d : {0.25, 1.0}) input.emplace_back(d, -1.0, 0.0, 0.0);
  const std::vector<glm::vec4> att = probe.run(input);

  for (size_t i = 0; i < input.size(); ++i) {
    const double d = input[i].x, r = input[i].y, gpu = att[i].x;
    CAPTURE(d);
    CAPTURE(r);
    CAPTURE(gpu);
    REQUIRE(std::isfinite(gpu));
    CHECK(gpu >= 0.0);
    CHECK(gpu <= 1.0);
    if (r <= 0.0 || d >= r) {
      CHECK(gpu == 0.0);
      continue;
    }
    const double x = d / r;
    const double window = std::clamp(1.0 - std::pow(x, 4.0), 0.0, 1.0);
    const double dc = std::max(d, 0.01);
    const double expected = std::min(window * window / (dc * dc), 1.0);
    CAPTURE(expected);
    // Near R, 1 - x^4 cancels: the error of x^4 (d / R may be off by 2.5 ulp in GLSL, 4x that after the power,
    // 7e-7 relative in all) reaches the result doubled and amplified by x^4 / (1 - x^4).
    const double x4 = std::pow(x, 4.0);
    CHECK(relativeError(gpu, expected) < 1e-5 + 1.5e-6 * x4 / (1.0 - x4));
  }
}
