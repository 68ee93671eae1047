// `pbr render --scene` refusing what it cannot render: a bad file or an unknown scene exits 1, an option the scene
// does not take exits 2, each with one line and before any context is made; and the environment options.
#include <doctest/doctest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "core/scene/assets.hpp"
#include "tests/cli_scene.hpp"
#include "tests/cli_util.hpp"

using pbr::test::isOneLine;
using pbr::test::kCliScene;
using pbr::test::PbrRun;
using pbr::test::runPbr;
using pbr::test::TempDir;

TEST_CASE("cli: a bad scene file or an unknown scene exits 1 with one line on stderr") {
  const TempDir dir;
  std::string bad = kCliScene;
  bad.replace(bad.find("\"radius\": 8"), 11, "\"radius\": -1");
  const std::string badFile = dir.write("bad.json", bad);
  const PbrRun run = runPbr(dir, {"render", "--scene", badFile, "--size", "64x36"});
  CHECK(run.exitCode == 1);
  CHECK(isOneLine(run.err));
  CHECK(run.err.find(badFile + ": lights[0].radius: expected a number in [0, 1e+12], got -1") != std::string::npos);
  CHECK(run.out.empty());  // rejected before a context is made

  const PbrRun unknown = runPbr(dir, {"render", "--scene", dir.file("nothing.json")});
  CHECK(unknown.exitCode == 1);
  CHECK(isOneLine(unknown.err));
  CHECK(unknown.err.find("no such file") != std::string::npos);
  CHECK(unknown.err.find("default, sphere-grid") != std::string::npos);
}

TEST_CASE("cli: --view-angle is refused for scenes other than fresnel-floor") {
  const TempDir dir;
  const std::string scene = dir.write("scene.json", kCliScene);
  for (const std::string& name : {std::string("default"), scene}) {
    CAPTURE(name);
    const PbrRun run = runPbr(dir, {"render", "--scene", name, "--view-angle", "30"});
    CHECK(run.exitCode == 2);
    CHECK(isOneLine(run.err));
    CHECK(run.err.find("--view-angle applies only to --scene fresnel-floor") != std::string::npos);
  }
}

TEST_CASE("cli: --gltf-scene, --animation and --time are refused for scenes without glTF models") {
  const TempDir dir;
  const std::string scene = dir.write("scene.json", kCliScene);
  for (const std::vector<std::string>& option :
       {std::vector<std::string>{"--gltf-scene", "1"}, {"--animation", "walk"}, {"--time", "1.5"}}) {
    CAPTURE(option[0]);
    const PbrRun run = runPbr(dir, {"render", "--scene", scene, option[0], option[1]});
    CHECK(run.exitCode == 2);
    CHECK(isOneLine(run.err));
    CHECK(run.err.find(option[0] + " applies only to scenes with glTF models") != std::string::npos);
  }
}

TEST_CASE("cli: --environment none takes a model's default sky away, and the reference never gets one") {
  const TempDir dir;
  const std::string box = pbr::assetPath("BoxTextured/glTF-Embedded/BoxTextured.gltf");
  for (const std::string command : {"render", "view"}) {
    CAPTURE(command);
    const PbrRun help = runPbr(dir, {command, "--help"});
    CHECK(help.out.find("--environment F.hdr|F.exr|sky|none") != std::string::npos);
    // Refused before a context or a window is made.
    const PbrRun run =
        runPbr(dir, {command, "--scene", box, "--environment", "none", "--environment-intensity", "2"});
    CHECK(run.exitCode == 2);
    CHECK(isOneLine(run.err));
    CHECK(run.err.find("--environment-intensity needs an environment") != std::string::npos);
    CHECK(run.out.empty());
  }
  // The reference refuses scenes with an environment: a default sky would fail it.
  const std::string out = dir.file("box.pfm");
  const PbrRun reference =
      runPbr(dir, {"reference", "--scene", box, "--size", "16x9", "--threads", "2", "--hdr", out});
  CAPTURE(reference.err);
  CHECK(reference.exitCode == 0);
  CHECK(std::filesystem::exists(out));
}
