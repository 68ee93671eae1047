// Timings users can trust by default: the first frame reported apart, warm medians, light lists sized before
// any timed frame, machine-readable single renders.
#include <doctest/doctest.h>

#include <fstream>
#include <regex>
#include <string>

#include <nlohmann/json.hpp>

#include "renderer/renderer.hpp"
#include "core/scene/builtin_scenes.hpp"
#include "tests/cli_util.hpp"
#include "tests/gl_test_context.hpp"

using namespace pbr;
using pbr::test::runPbr;
using pbr::test::TempDir;

TEST_CASE("warm timing: after warm-up no timed frame shades a cluster by fallback, 4096 lights on a small frame") {
  PBR_REQUIRE_GL();
  SceneParams params;
  params.lights = 4096;
  Scene scene = makeBuiltinScene("default", params);
  const ShaderLibrary shaders;
  Renderer renderer(shaders, scene, 160, 90);
  Profiler profiler(TimingMode::Serializing);
  const FrameOptions options;
  // The first frame of a light count sizes the list to its own demand.
  renderer.renderFrame(options, profiler);
  CHECK(renderer.lightStats().overflowedClusters == 0);
  // The same count, each light reaching twice as far: the demand outgrows the list, whose size later frames
  // read a few frames late, so this frame overflows and the check below is not vacuous.
  for (PointLight& l : scene.lights) l.radius *= 2.0f;
  renderer.setLights(scene.lights);
  renderer.renderFrame(options, profiler);
  CHECK(renderer.lightStats().overflowedClusters > 0);
  const WarmUpReport warm = renderer.warmUp(options, profiler, 0);
  CHECK(warm.listSizingFrames >= 1);
  CHECK(warm.overflowedClusters == 0);
  for (int frame = 0; frame < 5; ++frame) {
    renderer.renderFrame(options, profiler);
    CHECK(renderer.lightStats().overflowedClusters == 0);
  }
}

TEST_CASE("warm timing: default render output reports the first frame apart from the warm medians") {
  const TempDir dir;
  const pbr::test::PbrRun run =
      runPbr(dir, {"render", "--size", "96x54", "--lights", "4096", "--json", dir.file("r.json")});
  REQUIRE(run.exitCode == 0);
  CHECK(std::regex_search(run.out, std::regex("first frame \\(shader compilation, allocation; not in the medians\\): "
                                               "[0-9.]+ ms: gbuffer")));
  CHECK(run.out.find("warm-up: ") != std::string::npos);
  CHECK(run.out.find("median of 5 warm frames") != std::string::npos);
  CHECK(run.out.find("shaded by brute force") == std::string::npos);

  std::ifstream in(dir.file("r.json"));
  const nlohmann::json doc = nlohmann::json::parse(in);
  CHECK(doc["schema"] == "pbr-bench/1");
  CHECK(doc["settings"]["timed_frames"] == 5);
  const nlohmann::json& c = doc["configurations"].at(0);
  CHECK(c["lights"] == 4096);
  CHECK(c["frames"].size() == 5);
  CHECK(c["light_stats"]["overflowed_clusters"] == 0);
  const nlohmann::json& lighting = c["passes"]["lighting"];
  CHECK(lighting["p10_ms"].get<double>() <= lighting["median_ms"].get<double>());
  CHECK(lighting["median_ms"].get<double>() <= lighting["p90_ms"].get<double>());
  CHECK(lighting["median_ms"].get<double>() > 0.0);
  CHECK(doc["provenance"]["git_commit"].get<std::string>().size() > 0);
}
