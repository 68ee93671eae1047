// Golden frames of glTF models: each renders at a small fixed size and is compared pixel by pixel with a PNG of
// tests/golden/, so that a change anywhere in the frame fails, not only one that moves its mean or spread.
// PBR_UPDATE_GOLDEN=1 writes the PNGs instead of comparing (tests/README.md).
#include <doctest/doctest.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>

#include <glm/vec2.hpp>

#include "core/io/image_output.hpp"
#include "core/scene/assets.hpp"
#include "core/scene/builtin_scenes.hpp"
#include "core/scene/model_scene.hpp"
#include "tests/gl_test_context.hpp"
#include "tests/render_util.hpp"

namespace fs = std::filesystem;

namespace {

constexpr glm::ivec2 kSize{160, 90};

// Largest and mean absolute difference from the golden image, in 8-bit levels. The values at each comparison were
// measured on llvmpipe (Mesa 22.3.6, LLVM 15, 256-bit vectors), where the frame is identical run to run, with 1 to 7
// raster threads and with 128-bit vectors. The margin is for rounding of the size another driver or LLVM version
// brings, estimated by rendering into float32 instead of fp16 targets (`--hdr-format rgba32f`, `--gbuffer float`);
// the mean's margin stays below what 2% more exposure does, a change barely visible side by side, and the largest
// difference's catches local changes the mean misses (Hammon's visibility term moves two pixels of the sky-lit
// helmet by 10 levels, the mean by 0.02).
struct Tolerance {
  int maxLevels;
  double meanLevels;
};

bool updating() {
  const char* update = std::getenv("PBR_UPDATE_GOLDEN");
  return update && std::strcmp(update, "1") == 0;
}

// `scene` lit by the Radiance .hdr `file` in place of its own environment.
pbr::Scene withEnvironment(pbr::Scene scene, const std::string& file) {
  scene.environment = pbr::EnvironmentDesc{};
  scene.environment->file = file;
  return scene;
}

// The frame of `scene` at kSize: the PBR model, clustered culling, the scene's exposure; as `pbr render` draws it.
pbr::ImageRgba8 render(const pbr::Scene& scene) {
  pbr::FrameOptions options;
  options.exposure = scene.exposure;
  return pbr::test::renderScene(scene, kSize, options).ldr;
}

// Compares `frame` with tests/golden/NAME.png. A mismatch leaves the frame in golden_out/NAME.png of the working
// directory (build/ under ctest) to look at beside the golden one.
void checkGolden(const std::string& name, const pbr::ImageRgba8& frame, Tolerance tolerance) {
  const fs::path golden = fs::path(PBR_SOURCE_DIR) / "tests" / "golden" / (name + ".png");
  if (updating()) {
    pbr::writePng(golden.string(), frame);
    FAIL("PBR_UPDATE_GOLDEN=1: wrote " << golden.string() << " instead of comparing; review it, commit it and run "
                                       << "the test again without the variable");
  }
  REQUIRE_MESSAGE(fs::exists(golden), "no golden image " << golden.string() << "; PBR_UPDATE_GOLDEN=1 writes it");
  const pbr::ImageRgba8 expected = pbr::readPng(golden.string());
  REQUIRE(expected.width == frame.width);
  REQUIRE(expected.height == frame.height);
  const int maxLevels = pbr::test::maxByteDifference(frame, expected);
  const double meanLevels = pbr::test::meanAbsDifference(frame, expected);
  MESSAGE(name << ": max " << maxLevels << ", mean " << meanLevels << " levels from " << golden.string());
  CHECK(maxLevels <= tolerance.maxLevels);
  CHECK(meanLevels <= tolerance.meanLevels);
  if (maxLevels > tolerance.maxLevels || meanLevels > tolerance.meanLevels) {
    const fs::path out = fs::path("golden_out") / (name + ".png");
    fs::create_directories(out.parent_path());
    pbr::writePng(out.string(), frame);
    MESSAGE("the frame rendered now: " << fs::absolute(out).string());
  }
}

}  // namespace

TEST_CASE("gltf golden: DamagedHelmet.glb framed by the default rig under the procedural sky") {
  PBR_REQUIRE_GL();
  // The golden frame was made with the sky set as --environment sky sets it: a model's default must be the same.
  const pbr::Scene model = pbr::loadModelScene(pbr::assetPath("DamagedHelmet/glTF-Binary/DamagedHelmet.glb"));
  // float32 targets: max 1, mean 0.025 levels; 2% more exposure: max 2, mean 1.36.
  checkGolden("damaged_helmet_sky", render(model), Tolerance{4, 0.15});
}

TEST_CASE("gltf golden: Suzanne framed by the default rig under the shipped venice_sunset_1k.hdr") {
  PBR_REQUIRE_GL();
  const pbr::Scene model = pbr::loadModelScene(pbr::assetPath("Suzanne/glTF/Suzanne.gltf"));
  const std::string environment = pbr::assetPath("environments/venice_sunset_1k.hdr");
  // float32 targets: max 2, mean 0.023 levels; 2% more exposure: max 2, mean 1.30.
  checkGolden("suzanne_venice", render(withEnvironment(model, environment)), Tolerance{4, 0.15});
}

TEST_CASE("gltf golden: BoxTextured framed and lit by the default rig") {
  PBR_REQUIRE_GL();
  // The rig alone: the sky the model gets by default is checked by the helmet's frame.
  const pbr::Scene scene = pbr::loadModelScene(pbr::assetPath("BoxTextured/glTF-Embedded/BoxTextured.gltf"), {},
                                               pbr::DefaultEnvironment::None);
  // float32 targets: max 1, mean 0.015 levels; 2% more exposure: max 2, mean 0.27.
  checkGolden("box_textured", render(scene), Tolerance{4, 0.15});
}

TEST_CASE("gltf golden: the helmet scene, DamagedHelmet on a floor under 16 coloured lights") {
  PBR_REQUIRE_GL();
  // float32 targets: max 2, mean 0.11 levels; 2% more exposure: max 4, mean 0.66.
  checkGolden("helmet_scene", render(pbr::makeBuiltinScene("helmet")), Tolerance{4, 0.15});
}
