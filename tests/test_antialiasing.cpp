// Anti-aliasing of the display image (post/fxaa_pass.hpp): a bright tilted quad against black, whose edge is a
// staircase without it, takes intermediate values along the edge with FXAA while flat regions keep their values
// and the HDR radiance is untouched; `pbr render` anti-aliases its PNG by default and names a bad --aa.
#include <doctest/doctest.h>

#include <cstdlib>
#include <string>

#include "core/scene/scene_json.hpp"
#include "renderer/offscreen.hpp"
#include "tests/cli_util.hpp"
#include "tests/gl_test_context.hpp"

using pbr::test::TempDir;

namespace {

constexpr int kWidth = 96, kHeight = 64;

// An emissive quad turned 17 degrees in the image plane: its edges cross pixel rows and columns at shallow angles.
std::string edgeScene(const TempDir& dir) {
  return dir.write("edge.json", R"({"camera": {"position": [0, 0, 3], "target": [0, 0, 0], "fov_y_deg": 40},
    "objects": [{"shape": "plane", "transform": {"rotate_deg": [90, 0, 17], "scale": 0.6},
                 "material": {"base_color": 0.0, "emissive": [4, 4, 4]}}]})");
}

int green(const pbr::ImageRgba8& image, int x, int y) {
  return image.pixels[(static_cast<size_t>(y) * image.width + x) * 4 + 1];
}

}  // namespace

TEST_CASE("anti-aliasing: FXAA softens a high-contrast edge, leaves flat regions and the HDR image as they are") {
  PBR_REQUIRE_GL();
  const TempDir dir;
  const pbr::Scene scene = pbr::loadSceneFile(edgeScene(dir));
  const pbr::ShaderLibrary shaders;
  pbr::FrameOptions plain;
  pbr::FrameOptions fxaa = plain;
  fxaa.aa = pbr::AntiAliasing::Fxaa;
  const pbr::RenderedFrames a = pbr::renderOffscreen(shaders, scene, {kWidth, kHeight}, plain, 1);
  const pbr::RenderedFrames b = pbr::renderOffscreen(shaders, scene, {kWidth, kHeight}, fxaa, 1);

  CHECK(a.hdr.pixels == b.hdr.pixels);
  int edges = 0, softened = 0, flat = 0, flatChanged = 0, worstFlat = 0;
  for (int y = 1; y + 1 < kHeight; ++y) {
    for (int x = 1; x + 1 < kWidth; ++x) {
      const int centre = green(a.ldr, x, y);
      bool uniform = true;
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) uniform = uniform && green(a.ldr, x + dx, y + dy) == centre;
      }
      const int after = green(b.ldr, x, y);
      if (uniform) {
        ++flat;
        flatChanged += after != centre ? 1 : 0;
        worstFlat = std::max(worstFlat, std::abs(after - centre));
      } else {
        ++edges;
        softened += after > 16 && after < 200 ? 1 : 0;
      }
    }
  }
  // Without anti-aliasing the quad is a staircase of two values.
  int levels = 0;
  for (size_t i = 1; i < a.ldr.pixels.size(); i += 4) levels += a.ldr.pixels[i] > 16 && a.ldr.pixels[i] < 200 ? 1 : 0;
  MESSAGE(edges << " edge pixels, " << softened << " softened; " << flat << " flat, " << flatChanged
                << " changed (at most " << worstFlat << " levels); intermediate pixels without AA: " << levels);
  CHECK(levels == 0);
  CHECK(edges > 100);
  // Pixels beside a straight run of the staircase keep their value; those at its steps blend.
  CHECK(softened > edges / 5);
  CHECK(flat > 1000);
  CHECK(worstFlat <= 1);
}

TEST_CASE("anti-aliasing: pbr render anti-aliases its PNG by default, --aa none turns it off, a bad value is named") {
  PBR_REQUIRE_GL();
  const TempDir dir;
  const std::string scene = edgeScene(dir);
  auto render = [&](const std::vector<std::string>& extra) {
    std::vector<std::string> args = {"render", "--scene", scene, "--size", "48x32", "--frames", "1", "--warmup", "0"};
    args.insert(args.end(), extra.begin(), extra.end());
    return pbr::test::runPbr(dir, args);
  };
  const pbr::test::PbrRun byDefault = render({"--out", dir.file("default.png")});
  CHECK(byDefault.exitCode == 0);
  CHECK(byDefault.out.find("aa fxaa") != std::string::npos);
  CHECK(byDefault.out.find("\n  aa ") != std::string::npos);
  const pbr::test::PbrRun none = render({"--aa", "none", "--out", dir.file("none.png")});
  CHECK(none.exitCode == 0);
  CHECK(none.out.find("aa none") != std::string::npos);
  CHECK(none.out.find("\n  aa ") == std::string::npos);
  CHECK(pbr::test::readFile(dir.file("default.png")) != pbr::test::readFile(dir.file("none.png")));
  const pbr::test::PbrRun bad = render({"--aa", "smaa"});
  CHECK(bad.exitCode == 2);
  CHECK(pbr::test::isOneLine(bad.err));
  CHECK(bad.err.find("unknown anti-aliasing 'smaa' (expected none or fxaa)") != std::string::npos);
}
