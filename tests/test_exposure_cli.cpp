// The display transform's options on the command line: `pbr reference --out` encodes on the CPU what the post pass
// encodes on the GPU, for every tone curve; `--exposure auto` reports the metered EV100 (and in --json), gives way
// to a scene camera's exposure with a note, and is refused with --ev100; and `pbr render --settings` reproduces the
// frame of a --json report or a bench row (app/render_settings.hpp).
#include <doctest/doctest.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "core/gl/shader_library.hpp"
#include "core/scene/image.hpp"
#include "ibl/openexr_image.hpp"
#include "renderer/display_image.hpp"
#include "tests/cli_scene.hpp"
#include "tests/cli_util.hpp"
#include "tests/gl_test_context.hpp"

using pbr::test::isOneLine;
using pbr::test::PbrRun;
using pbr::test::runPbr;
using pbr::test::TempDir;

TEST_CASE("cli: pbr reference --out shows its radiance as the post pass does, under each tone curve") {
  PBR_REQUIRE_GL();
  const TempDir dir;
  const std::string scene = dir.write("scene.json", pbr::test::kCliScene);
  const pbr::ShaderLibrary shaders;
  for (const char* curve : {"aces-hill", "khronos-neutral", "agx"}) {
    CAPTURE(curve);
    const std::string hdr = dir.file(std::string(curve) + ".exr"), png = dir.file(std::string(curve) + ".png");
    const PbrRun run = runPbr(dir, {"reference", "--scene", scene, "--size", "32x18", "--threads", "2", "--hdr", hdr,
                                    "--out", png, "--tonemap", curve, "--exposure", "3"});
    CAPTURE(run.err);
    REQUIRE(run.exitCode == 0);
    const pbr::ImageRgba8 cpu = pbr::readPng(png);
    const pbr::ImageRgba8 gpu =
        pbr::displayImage(shaders, pbr::readOpenExr(hdr), 3.0f, pbr::parseToneCurve(curve));
    REQUIRE(cpu.pixels.size() == gpu.pixels.size());
    int worst = 0;
    for (size_t i = 0; i < cpu.pixels.size(); ++i) worst = std::max(worst, std::abs(cpu.pixels[i] - gpu.pixels[i]));
    CHECK(worst <= 1);
  }
  const PbrRun neither = runPbr(dir, {"reference", "--scene", scene, "--size", "32x18"});
  CHECK(neither.exitCode == 2);
  CHECK(isOneLine(neither.err));
}

TEST_CASE("cli: --exposure auto reports what it metered and yields to a scene camera's exposure") {
  PBR_REQUIRE_GL();
  const TempDir dir;
  const std::string scene = dir.write("scene.json", pbr::test::kCliScene);
  const std::vector<std::string> render = {"render", "--scene", scene, "--size", "64x36", "--frames", "1",
                                           "--warmup", "0"};
  std::vector<std::string> args = render;
  args.insert(args.end(), {"--exposure", "auto", "--json", dir.file("a.json")});
  const PbrRun metered = runPbr(dir, args);
  CAPTURE(metered.err);
  REQUIRE(metered.exitCode == 0);
  CHECK(metered.out.find("exposure: auto, EV100 ") != std::string::npos);
  CHECK(pbr::test::readFile(dir.file("a.json")).find("\"ev100_metered\"") != std::string::npos);

  args = render;
  args.insert(args.end(), {"--exposure", "auto", "--ev100", "3"});
  const PbrRun both = runPbr(dir, args);
  CHECK(both.exitCode == 2);
  CHECK(isOneLine(both.err));
  CHECK(both.err.find("--exposure auto") != std::string::npos);
  // Blinn-Phong frames are clamped: nothing to meter, refused before a context is made.
  args = render;
  args.insert(args.end(), {"--exposure", "auto", "--model", "blinn-phong"});
  const PbrRun clamped = runPbr(dir, args);
  CHECK(clamped.exitCode == 2);
  CHECK(isOneLine(clamped.err));
  CHECK(clamped.out.empty());

  std::string withCamera = pbr::test::kCliScene;
  withCamera.replace(withCamera.find("\"fov_y_deg\""), 0, "\"ev100\": 2, ");
  args = render;
  args[2] = dir.write("camera.json", withCamera);
  args.insert(args.end(), {"--exposure", "auto"});
  const PbrRun camera = runPbr(dir, args);
  REQUIRE(camera.exitCode == 0);
  CHECK(camera.out.find("note: the scene's camera sets EV100 2.00, which keeps priority over --exposure auto") !=
        std::string::npos);
  CHECK(camera.out.find("exposure: auto") == std::string::npos);
}

TEST_CASE("cli: pbr render --settings renders the frame a --json report was made of, options given here first") {
  PBR_REQUIRE_GL();
  const TempDir dir;
  const std::string scene = dir.write("scene.json", pbr::test::kCliScene);
  const PbrRun first = runPbr(dir, {"render", "--scene", scene, "--size", "64x36", "--frames", "1", "--warmup", "0",
                                    "--tonemap", "agx", "--culling", "none", "--tile", "16", "--exposure", "auto",
                                    "--out", dir.file("first.png"), "--json", dir.file("first.json")});
  REQUIRE(first.exitCode == 0);
  const std::string report = pbr::test::readFile(dir.file("first.json"));
  CHECK(report.find("\"render_settings\"") != std::string::npos);
  CHECK(report.find("\"--tonemap\": \"agx\"") != std::string::npos);
  // No scene, size or curve given: all from the report.
  const PbrRun again = runPbr(dir, {"render", "--settings", dir.file("first.json"), "--frames", "1", "--warmup", "0",
                                    "--out", dir.file("again.png")});
  CAPTURE(again.err);
  REQUIRE(again.exitCode == 0);
  CHECK(pbr::readPng(dir.file("again.png")).pixels == pbr::readPng(dir.file("first.png")).pixels);
  // An option given on the command line replaces the report's.
  const PbrRun other = runPbr(dir, {"render", "--settings", dir.file("first.json"), "--tonemap", "linear",
                                    "--frames", "1", "--warmup", "0", "--out", dir.file("other.png")});
  REQUIRE(other.exitCode == 0);
  CHECK(other.out.find("tonemap linear") != std::string::npos);
  CHECK(pbr::readPng(dir.file("other.png")).pixels != pbr::readPng(dir.file("first.png")).pixels);
  // A file without the record is refused naming it.
  const PbrRun none = runPbr(dir, {"render", "--settings", scene});
  CHECK(none.exitCode != 0);
  CHECK(isOneLine(none.err));
  CHECK(none.err.find("holds no render_settings") != std::string::npos);
}

TEST_CASE("cli: pbr render --settings F.json#K renders configuration K of a bench report as the bench drew it") {
  PBR_REQUIRE_GL();
  const TempDir dir;
  const PbrRun bench = runPbr(dir, {"bench", "--scene", "default", "--lights", "8,16", "--culling", "clustered",
                                    "--model", "pbr", "--size", "64x36", "--warmup", "1", "--frames", "1", "--tonemap",
                                    "khronos-neutral", "--json", dir.file("bench.json")});
  CAPTURE(bench.err);
  REQUIRE(bench.exitCode == 0);
  const PbrRun row = runPbr(dir, {"render", "--settings", dir.file("bench.json") + "#2", "--frames", "1", "--warmup",
                                  "0", "--out", dir.file("row.png")});
  CAPTURE(row.err);
  REQUIRE(row.exitCode == 0);
  const PbrRun same = runPbr(dir, {"render", "--scene", "default", "--lights", "16", "--culling", "clustered",
                                   "--model", "pbr", "--size", "64x36", "--tonemap", "khronos-neutral", "--aa", "none",
                                   "--frames", "1", "--warmup", "0", "--out", dir.file("same.png")});
  REQUIRE(same.exitCode == 0);
  CHECK(pbr::readPng(dir.file("row.png")).pixels == pbr::readPng(dir.file("same.png")).pixels);
  // A bench report needs its row named, and the row must exist.
  for (const std::string& settings : {dir.file("bench.json"), dir.file("bench.json") + "#3"}) {
    const PbrRun refused = runPbr(dir, {"render", "--settings", settings});
    CHECK(refused.exitCode != 0);
    CHECK(isOneLine(refused.err));
    CHECK(refused.err.find("bench.json") != std::string::npos);
  }
}
