// Anti-aliasing of the display image (post/fxaa_pass.hpp): a bright tilted quad against black, whose edge is a
// staircase without it, takes intermediate values along the edge with FXAA while flat regions keep their values
// and the HDR radiance is untouched; `pbr render` anti-aliases its PNG by default and names a bad --aa; the pass writes
// every pixel, copying those off an edge (by FXAA's threshold, evaluated here) and filtering the listed others.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "core/gl/program_cache.hpp"
#include "core/scene/scene_json.hpp"
#include "post/fxaa_pass.hpp"
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

TEST_CASE("anti-aliasing: FXAA copies every pixel off an edge and filters every pixel on one, at any frame size") {
  PBR_REQUIRE_GL();
  const pbr::ShaderLibrary shaders;
  pbr::ProgramCache programs(shaders);
  pbr::FxaaPass fxaa(programs);
  // Sizes that are not multiples of the 8x8 workgroups, the second larger, so that the edge list grows.
  for (const auto& [width, height] : {std::pair<int, int>{77, 45}, std::pair<int, int>{130, 71}}) {
    // Flat 5x3 blocks of a few greys and colours: edges along the blocks' borders, flat pixels inside them.
    std::vector<uint8_t> in(size_t(width) * height * 4);
    uint32_t state = 12345;
    std::vector<uint8_t> blockColour(size_t((width / 5 + 1) * (height / 3 + 1)) * 3);
    for (uint8_t& c : blockColour) {
      state = state * 1664525u + 1013904223u;
      c = uint8_t((state >> 24) & 0xC0);  // 0, 64, 128 or 192
    }
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < width; ++x) {
        const size_t block = size_t((y / 3) * (width / 5 + 1) + x / 5) * 3;
        for (int c = 0; c < 3; ++c) in[(size_t(y) * width + x) * 4 + c] = blockColour[block + c];
        in[(size_t(y) * width + x) * 4 + 3] = 255;
      }
    }
    const pbr::Texture display("test.display", GL_RGBA8, width, height), out("test.out", GL_RGBA8, width, height);
    glTextureSubImage2D(display.id(), 0, 0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, in.data());
    const uint8_t sentinel[4] = {1, 2, 3, 4};  // alpha 4: no input pixel has it
    glClearTexImage(out.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, sentinel);
    fxaa.render(display, out);
    std::vector<uint8_t> result(in.size());
    glGetTextureImage(out.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(result.size()), result.data());

    // FXAA's test for a pixel on an edge (shaders/post/fxaa.comp): the luma range of it and its four neighbours
    // against the larger of 0.0833 and 0.166 of their largest luma. Pixels within 1e-4 of it are not judged.
    const auto luma = [&](int x, int y) {
      const uint8_t* p = &in[(size_t(std::clamp(y, 0, height - 1)) * width + std::clamp(x, 0, width - 1)) * 4];
      return (0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2]) / 255.0;
    };
    int unwritten = 0, off = 0, offChanged = 0, on = 0, onChanged = 0;
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < width; ++x) {
        const size_t i = (size_t(y) * width + x) * 4;
        unwritten += result[i + 3] == 4 ? 1 : 0;
        const double l[5] = {luma(x, y), luma(x, y + 1), luma(x, y - 1), luma(x + 1, y), luma(x - 1, y)};
        const double most = *std::max_element(l, l + 5), least = *std::min_element(l, l + 5);
        const double margin = (most - least) - std::max(0.0833, most * 0.166);
        if (std::abs(margin) < 1e-4) continue;
        const bool changed = !std::equal(&result[i], &result[i] + 4, &in[i]);
        if (margin < 0.0) {
          ++off;
          offChanged += changed ? 1 : 0;
        } else {
          ++on;
          onChanged += changed ? 1 : 0;
        }
      }
    }
    MESSAGE(width << "x" << height << ": " << on << " pixels on an edge, " << onChanged << " changed; " << off
                  << " off, " << offChanged << " changed");
    CHECK(unwritten == 0);
    CHECK(offChanged == 0);
    CHECK(on > width * height / 10);
    CHECK(onChanged > on / 4);
  }
}
