// The README's Blender scene (scripts/blender_export_scene.py: point, spot and sun lights in the exporter's physical
// units, a camera) renders with `pbr render --scene file.gltf` alone as a photograph would: metered, mid-tones
// where the subject is, little clipped and little black.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdlib>
#include <string>
#include <vector>

#include "core/scene/image.hpp"
#include "tests/cli_util.hpp"
#include "tests/gl_test_context.hpp"

using pbr::test::TempDir;

TEST_CASE("blender export: a glTF with point, spot and sun lights in physical units and a camera renders as authored") {
  PBR_REQUIRE_GL();
  const TempDir dir;
  const std::string script = std::string(PBR_SOURCE_DIR) + "/scripts/blender_export_scene.py";
  REQUIRE(std::system(("python3 '" + script + "' '" + dir.path().string() + "' > /dev/null").c_str()) == 0);
  const std::string png = dir.file("blender.png");
  const pbr::test::PbrRun run = pbr::test::runPbr(
      dir, {"render", "--scene", dir.file("blender-export.gltf"), "--size", "320x180", "--frames", "1", "--warmup",
            "0", "--out", png});
  CAPTURE(run.err);
  REQUIRE(run.exitCode == 0);
  CHECK(run.out.find("3 lights + 1 directional") != std::string::npos);
  CHECK(run.out.find("as an incident-light meter reads it") != std::string::npos);
  CHECK(run.err.empty());

  // Rec. 709 luma of the encoded 8-bit values: a histogram a photographer would accept.
  const pbr::ImageRgba8 image = pbr::readPng(png);
  std::vector<int> luma;
  int clipped = 0;
  for (size_t i = 0; i < image.pixels.size(); i += 4) {
    const uint8_t* p = &image.pixels[i];
    luma.push_back(static_cast<int>(0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2] + 0.5));
    clipped += std::max({p[0], p[1], p[2]}) == 255 ? 1 : 0;
  }
  std::sort(luma.begin(), luma.end());
  const double n = static_cast<double>(luma.size());
  const int p5 = luma[static_cast<size_t>(0.05 * n)], median = luma[luma.size() / 2];
  const int p95 = luma[static_cast<size_t>(0.95 * n)];
  MESSAGE("luma p5 " << p5 << ", median " << median << ", p95 " << p95 << "; clipped " << clipped / n * 100.0
                     << " %");
  CHECK(median > 70);
  CHECK(median < 190);
  CHECK(p5 > 10);
  CHECK(p95 < 250);
  CHECK(clipped < 0.02 * n);
}
