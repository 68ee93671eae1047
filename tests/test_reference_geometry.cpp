// The reference's mesh geometry against the exact shapes: the error of a tessellation shrinks as it grows, a plane's
// two triangles are the plane, and `pbr reference --geometry` picks either.
#include <doctest/doctest.h>

#include <cmath>
#include <regex>
#include <string>

#include "app/accuracy/accuracy_variants.hpp"
#include "core/scene/mesh.hpp"
#include "reference/reference_renderer.hpp"
#include "tests/cli_util.hpp"
#include "tests/reference_spheres.hpp"

using namespace pbr;
using namespace pbr::reference;
using namespace pbr::test;

namespace {

// sqrt(sum (a - b)^2 / sum b^2) over the colour channels of the pixels inside the same object in both frames.
double relativeRmse(const ReferenceFrame& a, const ReferenceFrame& b) {
  double num = 0.0, den = 0.0;
  for (int y = 0; y < b.radiance.height; ++y) {
    for (int x = 0; x < b.radiance.width; ++x) {
      const size_t i = size_t(y) * b.radiance.width + x;
      if (b.objectIds[i] < 0 || a.objectIds[i] != b.objectIds[i] || !a.interior(x, y) || !b.interior(x, y)) continue;
      for (int c = 0; c < 3; ++c) {
        const double r = b.radiance.at(x, y)[c], d = a.radiance.at(x, y)[c] - r;
        num += d * d;
        den += r * r;
      }
    }
  }
  return std::sqrt(num / den);
}

}  // namespace

TEST_CASE("reference meshes: the geometry error against the exact shapes shrinks as the tessellation grows") {
  auto geometryError = [](int segments, int rings) {
    const Scene s = sphereScene(makeSphereMesh(segments, rings));
    return relativeRmse(renderWith(s, Geometry::Meshes), renderWith(s, Geometry::Analytic));
  };
  const double coarse = geometryError(8, 4), medium = geometryError(32, 16), fine = geometryError(128, 64);
  MESSAGE("geometry error: 8x4 " << coarse << ", 32x16 " << medium << ", 128x64 " << fine);
  CHECK(fine > 0.0);
  // Interpolated normals err by O(h^2) in the facet size h: each fourfold refinement divides the error by about 16.
  CHECK(coarse > 4.0 * medium);
  CHECK(medium > 8.0 * fine);
}

TEST_CASE("reference meshes: a plane's two triangles are the exact plane") {
  const Scene floor = loadAccuracyScene("fresnel-floor:65").scene;
  const ReferenceFrame meshes = renderWith(floor, Geometry::Meshes), exact = renderWith(floor, Geometry::Analytic);
  CHECK(meshes.objectIds == exact.objectIds);
  CHECK(relativeRmse(meshes, exact) < 1e-6);
}

TEST_CASE("reference meshes: pbr reference --geometry picks the geometry, meshes by default") {
  const test::TempDir dir;
  const test::PbrRun help = test::runPbr(dir, {"reference", "--help"});
  CHECK(help.exitCode == 0);
  CHECK(std::regex_search(help.out, std::regex("--geometry G +meshes .*\\s+\\(default\\s+meshes\\)")));
  const test::PbrRun byDefault = test::runPbr(dir, {"reference", "--size", "32x18", "--hdr", dir.file("a.pfm")});
  CHECK(byDefault.exitCode == 0);
  CHECK(byDefault.out.find("(mesh geometry)") != std::string::npos);
  const test::PbrRun analytic =
      test::runPbr(dir, {"reference", "--size", "32x18", "--geometry", "analytic", "--hdr", dir.file("b.pfm")});
  CHECK(analytic.exitCode == 0);
  CHECK(analytic.out.find("(analytic geometry)") != std::string::npos);
  const test::PbrRun bad = test::runPbr(dir, {"reference", "--geometry", "nurbs", "--hdr", dir.file("x.pfm")});
  CHECK(bad.exitCode == 2);
  CHECK(test::isOneLine(bad.err));
}
