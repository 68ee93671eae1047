// Command lines that name the wrong argument and frames over the limits: each is refused before any context is
// made, with exit code 2 and one short line on stderr naming the file or option.
#include <doctest/doctest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "renderer/frame_limits.hpp"
#include "renderer/renderer_config.hpp"
#include "tests/cli_util.hpp"
#include "tests/refusal_checks.hpp"

namespace fs = std::filesystem;
using namespace pbr::test;
using Run = PbrRun;

TEST_CASE("hostile outputs: an unknown capture extension fails before rendering with exit 2 naming the file") {
  const TempDir dir;
  const std::vector<std::vector<std::string>> cases = {
      tinyRender({"--out", dir.file("f.gif")}),
      tinyRender({"--hdr", dir.file("f.hdr")}),
      tinyRender({"--hdr", "/dev/full"}),  // a device says nothing of the format
      tinyRender({"--json", dir.file("f.txt")}),
      {"reference", "--size", "32x18", "--hdr", dir.file("f.png")},
      {"view", "--quit-after", "1", "--screenshot", dir.file("f.bmp")},
      {"bench", "--lights", "8", "--frames", "1", "--csv", dir.file("f.json")},
      {"bench", "--lights", "8", "--frames", "1", "--json", dir.file("f.csv")},
      {"bench", "--lights", "8", "--frames", "1", "--trace", dir.file("f.trace")},
      {"bench-merge", dir.file("missing.json"), "--csv", dir.file("f.txt")},
      {"bench-merge", dir.file("missing.json"), "--trace", dir.file("f.trace")},
  };
  for (const auto& args : cases) {
    const std::string& path = args[args.size() - 1];
    CAPTURE(path);
    const Run run = runPbr(dir, args);
    CHECK(run.exitCode == 2);
    checkOneLineNaming(run, path);
    CHECK(run.out.empty());
    if (path != "/dev/full") CHECK_FALSE(fs::exists(path));
  }
}

TEST_CASE("hostile outputs: an option missing its value is named, not the option after it") {
  const TempDir dir;
  struct Case {
    std::vector<std::string> args;
    std::string message;
  };
  const std::vector<Case> cases = {
      {{"render", "--lights", "--size", "160x90"}, "--lights expects a value (N)"},
      {{"render", "--size", "160x90", "--out"}, "--out expects a value (F.png|F.jpg)"},
      {{"render", "--out=", "--size", "160x90"}, "--out expects a value (F.png|F.jpg), got an empty one"},
      {{"render", "--scene", ""}, "--scene expects a value (NAME|FILE), got an empty one"},
      {{"render", "--lights", "8", "--lights=16"}, "--lights is given more than once"},
      {{"render", "--stats", "--stats"}, "--stats is given more than once"},
      {{"bench", "--csv", "--json", "b.json"}, "--csv expects a value (F.csv)"},
  };
  for (const Case& c : cases) {
    CAPTURE(c.message);
    const Run run = runPbr(dir, c.args);
    CHECK(run.exitCode == 2);
    checkOneLineNaming(run, c.message);
    CHECK(run.out.empty());
  }
}

TEST_CASE("hostile outputs: the frame-size check names the option and the limit it is over") {
  pbr::RendererConfig lean;
  // G-buffer, HDR, LDR and the LDR before anti-aliasing, captures (RGBA8 and RGBA32F, buffer and image each), the
  // lighting pass's running sums, the efficiency channel's pair counts, the shadows channel's light sums.
  CHECK(pbr::frameBytesPerPixel(lean) == 16 + 8 + 4 + 4 + 8 + 32 + 16 + 8 + 8);
  pbr::RendererConfig wide;
  wide.gbuffer = pbr::GBufferPrecision::Float;
  wide.hdrFormat = pbr::HdrFormat::Rgba32f;
  CHECK(pbr::frameBytesPerPixel(wide) == 44 + 16 + 4 + 4 + 8 + 32 + 16 + 8 + 8);
  // Transmissive materials add the opaque frame's copy with its mip chain: 4/3 of RGBA16F's 8 bytes, rounded up.
  CHECK(pbr::frameBytesPerPixel(lean, {}, true) == pbr::frameBytesPerPixel(lean) + 11);

  const pbr::FrameLimits limits{8192, 1'000'000'000};
  CHECK_NOTHROW(pbr::checkFrameSize(8192, 16, "--size", 68, limits));
  CHECK_THROWS_WITH(pbr::checkFrameSize(8193, 16, "--size", 68, limits),
                    "--size 8193x16: over the OpenGL limit of 8192 pixels a side (GL_MAX_TEXTURE_SIZE)");
  CHECK_THROWS_WITH(pbr::checkFrameSize(16, 8193, "--pair-size", 68, limits),
                    "--pair-size 16x8193: over the OpenGL limit of 8192 pixels a side (GL_MAX_TEXTURE_SIZE)");
  // 4000 x 4000 x 68 = 1.088 GB against 1 GB.
  CHECK_THROWS_WITH(pbr::checkFrameSize(4000, 4000, "--size", 68, limits),
                    "--size 4000x4000: the frame needs about 1.1 GB (68 bytes per pixel), over the 1.0 GB of memory "
                    "available");
  CHECK_NOTHROW(pbr::checkFrameSize(3800, 3800, "--size", 68, limits));
}

TEST_CASE("hostile arguments: conflicting or malformed choices are refused naming what conflicts") {
  const TempDir dir;
  const std::string file = dir.write("f.json", "{}");
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {tinyRender({"--variant", "visibility=exact,visibility=hammon"}),
       "variant key 'visibility' given twice (in 'visibility=exact,visibility=hammon')"},
      {tinyRender({"--variant", "vis=exact,visibility=hammon"}), "variant key 'visibility' given twice"},
      {tinyRender({"--variant", "lobe=sg"}), "--variant lobe=sg: lobe is a term of the blinn-phong model, not of "
                                             "--model pbr"},
      {tinyRender({"--model", "blinn-phong", "--variant", "ndf=beckmann"}),
       "ndf is a term of the pbr model, not of --model blinn-phong"},
      {tinyRender({"--variant", "study", "--visibility", "hammon"}),
       "--visibility and --variant study both choose the visibility term"},
      {tinyRender({"--model", "blinn-phong", "--visibility", "hammon"}),
       "--visibility is a term of the pbr model, not of --model blinn-phong"},
      {{"reference", "--size", "8x8", "--hdr", dir.file("r.pfm"), "--variant", "fresnel=schlick,fresnel=exact"},
       "variant key 'fresnel' given twice"},
      {{"bench", "--pair-cost", "exact,exact"}, "variant 'exact' given twice (in 'exact,exact')"},
      {{"accuracy", "--variants", "exact,exact"}, "variant 'exact' given twice"},
      {{"accuracy", "--scenes", "fresnel-floor:abc"},
       "--scenes fresnel-floor:abc: expected NAME or fresnel-floor:DEGREES, the view angle a number (got 'abc')"},
      {{"accuracy", "--scenes", "fresnel-floor:40:2"}, "the view angle a number (got '40:2')"},
      {{"accuracy", "--scenes", "sphere-grid:40"},
       "--scenes sphere-grid:40: a view angle applies only to fresnel-floor"},
      {{"view", "--quit-after", "1", "--env-dir", file}, "--env-dir " + file + ": not a folder"},
  };
  for (const auto& [args, line] : cases) {
    CAPTURE(line);
    const Run run = runPbr(dir, args);
    CHECK(run.exitCode == 2);
    checkOneLineNaming(run, line);
  }
}

TEST_CASE("hostile arguments: an unreadable scene and an output folder a file is in the way of are named") {
  const TempDir dir;
  const std::string file = dir.write("f.json", "{}");
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {tinyRender({"--scene", "/proc/self/mem"}), "pbr render: /proc/self/mem: cannot read: Input/output error"},
      {{"experiment", "fresnel", "--out-dir", file}, "pbr experiment: --out-dir " + file +
                                                     ": cannot make the folder: Not a directory"},
      // A name of 5,000 characters: the system's reason, the name's ends kept and the line short.
      {tinyRender({"--scene", std::string(5000, 'a')}),
       "pbr render: " + std::string(100, 'a') + "..." + std::string(100, 'a') + ": File name too long"},
  };
  for (const auto& [args, line] : cases) {
    CAPTURE(line);
    const Run run = runPbr(dir, args);
    CHECK(run.exitCode == 1);
    CHECK(run.err == line + "\n");
    CHECK(run.err.size() < 300);
  }
}
