#include <doctest/doctest.h>

#include <cmath>
#include <initializer_list>

#include "reference/directional_albedo.hpp"
#include "core/builtin_scenes.hpp"
#include "reference/reference_brdf.hpp"
#include "reference/reference_renderer.hpp"

using namespace pbr::reference;

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
