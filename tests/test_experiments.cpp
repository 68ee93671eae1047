#include <doctest/doctest.h>

#include <iterator>

#include "app/experiments/experiments.hpp"
#include "core/scene/builtin_scenes.hpp"
#include "core/scene/tone_curve.hpp"
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

TEST_CASE("experiments: tonemap, every curve rises from black to white over the ramp, and the strip holds each") {
  PBR_REQUIRE_GL();
  const ShaderLibrary shaders;
  const Scene scene = makeBuiltinScene("default");
  const ExperimentResult r = runToneMapExperiment(shaders, {96, 54}, scene);
  REQUIRE(r.table.columns.size() == std::size(kToneCurves));
  REQUIRE(r.table.x.size() == 65);  // 16 stops in quarters, both ends
  for (const std::string& curve : r.table.columns) {
    CAPTURE(curve);
    CHECK(r.table.at(0, curve) <= 10);                      // 8 stops under mid grey: next to black
    CHECK(r.table.at(r.table.x.size() - 1, curve) >= 250);  // 8 over: white
    for (size_t i = 1; i < r.table.x.size(); ++i) CHECK(r.table.at(i, curve) >= r.table.at(i - 1, curve));
  }
  // Mid grey itself: the linear clamp shows 0.18 as sRGB 118; ACES Hill darker, AgX brighter (their definitions).
  const size_t grey = 32;
  REQUIRE(r.table.x[grey] == 0.0);
  CHECK(r.table.at(grey, "linear") == 118);
  CHECK(r.table.at(grey, "aces-hill") < r.table.at(grey, "linear"));
  REQUIRE(r.images.size() == 1);
  const ImageRgba8& strip = r.images[0].image;
  CHECK(strip.height == 54);
  CHECK(strip.width == int(std::size(kToneCurves)) * 54 + (int(std::size(kToneCurves)) - 1) * 4);
  // The panels differ: each is its own curve.
  const auto panel = [&](int p, int x, int y) { return strip.pixels[(size_t(y) * strip.width + p * 58 + x) * 4]; };
  int differing = 0;
  for (int y = 0; y < 54; ++y) differing += panel(0, 27, y) != panel(3, 27, y);
  CHECK(differing > 10);
}
