// `pbr render --scene` with scene files: a JSON file renders, a bad one exits 1 with one line.
#include <doctest/doctest.h>

#include <string>

#include "tests/cli_util.hpp"
#include "tests/gl_test_context.hpp"

using pbr::test::isOneLine;
using pbr::test::PbrRun;
using pbr::test::runPbr;
using pbr::test::TempDir;

namespace {

const char* kScene = R"({
  "camera": {"position": [0, 2, 5], "target": [0, 0.5, 0], "fov_y_deg": 45, "near": 0.5, "far": 20},
  "ambient": 0.05,
  "objects": [{"shape": "plane", "transform": {"scale": 8}}, {"shape": "sphere", "transform": {"translate": [0, 0.5, 0]}}],
  "lights": [{"position": [1, 2, 2], "luminous_power": 200, "radius": 8}],
  "random_lights": {"count": 8, "bounds": [[-2, 0.2, -2], [2, 1.5, 2]], "radius": [1, 2], "luminous_power": [5, 10]}
})";

}  // namespace

TEST_CASE("cli: render --scene FILE.json renders the file's scene") {
  PBR_REQUIRE_GL();
  const TempDir dir;
  const std::string scene = dir.write("scene.json", kScene), png = dir.file("f.png");
  const PbrRun run = runPbr(dir, {"render", "--scene", scene, "--size", "64x36", "--out", png});
  CHECK(run.exitCode == 0);
  CHECK(run.err.empty());
  CHECK(run.out.find("scene: scene, 64x36, 9 lights") != std::string::npos);
  CHECK(std::filesystem::exists(png));
  const PbrRun more = runPbr(dir, {"render", "--scene", scene, "--size", "64x36", "--lights", "20"});
  CHECK(more.exitCode == 0);
  CHECK(more.out.find("21 lights") != std::string::npos);
}

TEST_CASE("cli: a bad scene file or an unknown scene exits 1 with one line on stderr") {
  const TempDir dir;
  std::string bad = kScene;
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
  const std::string scene = dir.write("scene.json", kScene);
  for (const std::string& name : {std::string("default"), scene}) {
    CAPTURE(name);
    const PbrRun run = runPbr(dir, {"render", "--scene", name, "--view-angle", "30"});
    CHECK(run.exitCode == 2);
    CHECK(isOneLine(run.err));
    CHECK(run.err.find("--view-angle applies only to --scene fresnel-floor") != std::string::npos);
  }
}
