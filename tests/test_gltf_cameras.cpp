// glTF cameras: a model's first camera is the default view, `--camera N` picks another and `--camera auto` frames
// the model; where a quad lands in each frame is computed here from the camera's own matrices.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "core/scene/image.hpp"
#include "tests/cli_util.hpp"
#include "tests/gl_test_context.hpp"
#include "tests/gltf_builder.hpp"

using pbr::test::GltfBuilder;
using pbr::test::TempDir;

namespace {

constexpr int kWidth = 64, kHeight = 36;
constexpr double kYfov = 0.8;

// Red channel of pixel (x, y) of a frame `pbr render` writes with `extra` options.
struct Frame {
  pbr::ImageRgba8 image;
  int red(int x, int y) const { return image.pixels[(size_t(y) * image.width + x) * 4]; }
};

Frame render(const TempDir& dir, const std::string& model, const std::vector<std::string>& extra) {
  // No environment: the quad glows on black.
  std::vector<std::string> args = {"render", "--scene", model, "--size", "64x36", "--frames", "1", "--warmup", "0",
                                   "--environment", "none", "--out", dir.file("camera.png")};
  args.insert(args.end(), extra.begin(), extra.end());
  const pbr::test::PbrRun run = pbr::test::runPbr(dir, args);
  CAPTURE(run.err);
  REQUIRE(run.exitCode == 0);
  return {pbr::readPng(dir.file("camera.png"))};
}

// The pixel where a camera at `eye` looking down -Z sees `point`: its view and projection, as glTF defines them.
glm::ivec2 project(const glm::vec3& eye, const glm::vec3& point) {
  const glm::mat4 view = glm::lookAt(eye, eye + glm::vec3(0, 0, -1), glm::vec3(0, 1, 0));
  const glm::mat4 projection = glm::perspective(float(kYfov), float(kWidth) / kHeight, 0.1f, 100.0f);
  const glm::vec4 clip = projection * view * glm::vec4(point, 1.0f);
  const glm::vec2 ndc = glm::vec2(clip) / clip.w;
  return {int((ndc.x * 0.5f + 0.5f) * kWidth), int((0.5f - ndc.y * 0.5f) * kHeight)};
}

}  // namespace

TEST_CASE("gltf cameras: the first camera is the default view and --camera picks another or frames the model") {
  PBR_REQUIRE_GL();
  const TempDir dir;
  // A white-emitting 2 x 2 quad at the origin facing +Z, on black.
  GltfBuilder b;
  const int glow = b.addMaterial({{"emissiveFactor", {1.0, 1.0, 1.0}},
                                  {"pbrMetallicRoughness", {{"baseColorFactor", {0.0, 0.0, 0.0, 1.0}}}}});
  pbr::test::QuadSpec quad;
  quad.material = glow;
  b.addRootNode({{"mesh", pbr::test::addQuad(b, quad)}});
  b.doc["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", kYfov}, {"znear", 0.1}, {"zfar", 100.0}}}},
                      {{"type", "perspective"}, {"perspective", {{"yfov", kYfov}, {"znear", 0.1}}}}};
  const glm::vec3 front{0.0f, 0.0f, 4.0f}, aside{1.5f, 0.0f, 4.0f};
  b.addRootNode({{"translation", {front.x, front.y, front.z}}, {"camera", 0}});
  b.addRootNode({{"translation", {aside.x, aside.y, aside.z}}, {"camera", 1}});
  const std::string model = b.writeGltf(dir.path(), "cameras");

  const glm::ivec2 centre{kWidth / 2, kHeight / 2};
  CHECK(project(front, glm::vec3(0.0f)) == centre);
  const Frame first = render(dir, model, {});
  CHECK(first.red(centre.x, centre.y) > 200);
  CHECK(first.red(2, centre.y) < 10);  // beyond the quad's edge

  // Seen from 1.5 to the right the quad's centre lands a quarter of the way in; the frame centre is off the quad.
  const glm::ivec2 shifted = project(aside, glm::vec3(0.0f));
  CHECK(shifted.x < kWidth / 3);
  const Frame second = render(dir, model, {"--camera", "1"});
  CHECK(second.red(shifted.x, shifted.y) > 200);
  CHECK(second.red(centre.x, centre.y) < 10);
  CHECK(render(dir, model, {"--camera", "0"}).image.pixels == first.image.pixels);

  // auto frames the quad's bounding sphere: centred, and smaller than the first camera shows it (it sits farther).
  const Frame framed = render(dir, model, {"--camera", "auto"});
  CHECK(framed.red(centre.x, centre.y) > 200);

  const pbr::test::PbrRun outOfRange = pbr::test::runPbr(dir, {"render", "--scene", model, "--camera", "2"});
  CHECK(outOfRange.exitCode == 2);
  CHECK(outOfRange.err.find("--camera expects an integer in [0, 1], got '2'") != std::string::npos);
}
