#include <doctest/doctest.h>

#include "app/experiments/experiments.hpp"
#include "tests/gl_test_context.hpp"

using namespace pbr;

TEST_CASE("experiments: saturation, Blinn-Phong saturates from 2 co-located lights on, PBR never") {
  PBR_REQUIRE_GL();
  const ShaderLibrary shaders;
  const ExperimentResult r = runSaturationExperiment(shaders, {96, 54}, 6);
  REQUIRE(r.table.x.size() == 6);
  // One light of colour 1 at distance 1 gives 0.8 diffuse + 0.04 specular on the wall: below 255.
  CHECK(r.table.at(0, "blinn_phong") == 0);
  for (size_t i = 1; i < r.table.x.size(); ++i) {
    CAPTURE(r.table.x[i]);
    CHECK(r.table.at(i, "blinn_phong") > r.table.at(i - 1, "blinn_phong"));
    CHECK(r.table.at(i, "pbr") == 0);
  }
  CHECK(r.table.at(0, "pbr") == 0);
}

TEST_CASE("experiments: fresnel, PBR reflectance rises with the view angle, Blinn-Phong stays at F0") {
  PBR_REQUIRE_GL();
  const ShaderLibrary shaders;
  const ExperimentResult r = runFresnelExperiment(shaders, {96, 54});
  REQUIRE(r.table.x.size() == 4);
  for (size_t i = 0; i < r.table.x.size(); ++i) {
    CAPTURE(r.table.x[i]);
    // Blinn-Phong's specular colour is F0 = 0.04 for a dielectric, at every angle (fp16 storage: 1e-3).
    CHECK(r.table.at(i, "blinn_phong") == doctest::Approx(0.04).epsilon(2e-3));
    if (i > 0) CHECK(r.table.at(i, "pbr") > r.table.at(i - 1, "pbr") * 1.1);
  }
  CHECK(r.table.at(3, "pbr") > 10.0 * r.table.at(0, "pbr"));
  CHECK(r.images.size() == 8);
}
