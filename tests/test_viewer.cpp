// The interactive viewer, driven as a user would through its key handler, in a real GLFW window: these cases need
// a display and run under Xvfb (tests/under_xvfb.sh), in their own executable.
#include "app/viewer/viewer.hpp"

#include <GLFW/glfw3.h>
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "app/scene_source.hpp"
#include "tests/cli_util.hpp"

using pbr::ImageRgba8;
using pbr::Viewer;
using pbr::test::runPbr;
using pbr::test::TempDir;

namespace {

constexpr glm::ivec2 kSize{160, 90};

// A paused viewer of the default scene, so that its lights stay where the headless render has them. Null (and the
// case failed, unless PBR_ALLOW_NO_GL=1) when no window can be opened.
std::unique_ptr<Viewer> openViewer(glm::ivec2 size = kSize, const std::string& screenshot = "") {
  pbr::ViewerOptions options;
  options.size = size;
  options.screenshot = screenshot;
  options.paused = true;
  pbr::Scene scene = pbr::resolveScene(options.sceneName, options.sceneParams);
  options.frame.exposure = scene.exposure;
  try {
    return std::make_unique<Viewer>(options, std::move(scene));
  } catch (const pbr::ContextError& e) {
    const char* allow = std::getenv("PBR_ALLOW_NO_GL");
    if (allow && std::strcmp(allow, "1") == 0) {
      MESSAGE("no window (" << std::string(e.what()) << "); allowed by PBR_ALLOW_NO_GL=1");
    } else {
      FAIL("no OpenGL 4.5 window: " << std::string(e.what())
                                    << " (run under tests/under_xvfb.sh; set PBR_ALLOW_NO_GL=1 to allow this)");
    }
    return nullptr;
  }
}

// A few frames, so that the clustered path has sized its index list from measured demand, then what is shown.
ImageRgba8 show(Viewer& viewer, int frames = 3) {
  for (int i = 0; i < frames; ++i) viewer.frame();
  return viewer.screenshot();
}

struct Difference {
  double mean = 0.0;
  int max = 0;
};

Difference compare(const ImageRgba8& a, const ImageRgba8& b) {
  REQUIRE(a.width == b.width);
  REQUIRE(a.height == b.height);
  Difference d;
  for (size_t i = 0; i < a.pixels.size(); ++i) {
    const int delta = std::abs(int(a.pixels[i]) - int(b.pixels[i]));
    d.mean += delta;
    d.max = std::max(d.max, delta);
  }
  d.mean /= double(std::max<size_t>(a.pixels.size(), 1));
  return d;
}

// `pbr render` of the default scene at `size`, with `extra` arguments, as the reference for a viewer frame: with
// `aa` none for the viewers made here (the library's default), fxaa for `pbr view` (its default, as `pbr render`'s).
ImageRgba8 headless(const TempDir& dir, glm::ivec2 size, std::vector<std::string> extra = {},
                    const std::string& aa = "none") {
  const std::string out = dir.file("headless.png");
  std::vector<std::string> args = {"render", "--size", std::to_string(size.x) + "x" + std::to_string(size.y),
                                   "--frames", "2", "--aa", aa, "--out", out};
  args.insert(args.end(), extra.begin(), extra.end());
  const pbr::test::PbrRun run = runPbr(dir, args);
  REQUIRE_MESSAGE(run.exitCode == 0, run.err);
  return pbr::readPng(out);
}

void checkMatches(const ImageRgba8& shown, const ImageRgba8& reference) {
  const Difference d = compare(shown, reference);
  CAPTURE(d.mean);
  CAPTURE(d.max);
  CHECK(d.mean < 1.0);
  CHECK(d.max < 8);
}

}  // namespace

TEST_CASE("view: keys switch the shading model and culling of the same frame") {
  const auto viewer = openViewer();
  if (!viewer) return;
  const ImageRgba8 pbrClustered = show(*viewer);
  CHECK(pbrClustered.width == kSize.x);
  CHECK(pbrClustered.height == kSize.y);

  viewer->handleKey(GLFW_KEY_C);
  CHECK(std::string(toString(viewer->frameOptions().culling)) == "none");
  // Cluster lists are sorted, so both paths add the same lights in the same order.
  CHECK(show(*viewer).pixels == pbrClustered.pixels);

  viewer->handleKey(GLFW_KEY_M);
  CHECK(std::string(toString(viewer->frameOptions().model)) == "blinn-phong");
  const ImageRgba8 blinnBrute = show(*viewer);
  CHECK(compare(blinnBrute, pbrClustered).mean > 5.0);
  viewer->handleKey(GLFW_KEY_C);
  CHECK(show(*viewer).pixels == blinnBrute.pixels);

  viewer->handleKey(GLFW_KEY_M);
  CHECK(show(*viewer).pixels == pbrClustered.pixels);

  // Exposure: half a stop up brightens the PBR frame, and back down restores it.
  viewer->handleKey(GLFW_KEY_EQUAL);
  CHECK(compare(show(*viewer), pbrClustered).mean > 1.0);
  viewer->handleKey(GLFW_KEY_MINUS);
  CHECK(compare(show(*viewer), pbrClustered).max <= 1);
}

TEST_CASE("view: V cycles the debug views and back to the final frame") {
  const auto viewer = openViewer();
  if (!viewer) return;
  const ImageRgba8 final = show(*viewer);
  std::vector<ImageRgba8> views;
  for (const pbr::DebugChannel channel : pbr::kDebugChannels) {
    viewer->handleKey(GLFW_KEY_V);
    CAPTURE(pbr::toString(channel));
    CHECK((viewer->view() == channel));
    views.push_back(show(*viewer, 1));
    CHECK(compare(views.back(), final).mean > 5.0);
  }
  // Every view shows something different from every other.
  for (size_t i = 0; i < views.size(); ++i) {
    for (size_t j = i + 1; j < views.size(); ++j) CHECK(views[i].pixels != views[j].pixels);
  }
  // The metalness view of the default scene: the floor is a dielectric (black), the sphere grid's right column
  // is fully metallic (white).
  const ImageRgba8& metalness = views[3];
  const auto at = [&](int x, int y) { return metalness.pixels[(size_t(y) * metalness.width + x) * 4]; };
  CHECK(at(2, metalness.height - 3) == 0);
  viewer->handleKey(GLFW_KEY_V);
  CHECK(std::string(pbr::viewName(viewer->view())) == "final");
  CHECK(show(*viewer, 1).pixels == final.pixels);
}

TEST_CASE("view: [ and ] regenerate the lights, P animates them") {
  const auto viewer = openViewer();
  if (!viewer) return;
  const ImageRgba8 start = show(*viewer);
  CHECK(viewer->lightCount() == 256);
  viewer->handleKey(GLFW_KEY_LEFT_BRACKET);
  CHECK(viewer->lightCount() == 128);
  CHECK(show(*viewer).pixels != start.pixels);
  viewer->handleKey(GLFW_KEY_RIGHT_BRACKET);
  CHECK(viewer->lightCount() == 256);
  // The scene's seeded generator makes the same 256 lights again.
  CHECK(show(*viewer).pixels == start.pixels);

  CHECK(viewer->lightsPaused());
  viewer->handleKey(GLFW_KEY_P);
  CHECK_FALSE(viewer->lightsPaused());
  // Moving lights change the frame however short the frames are: llvmpipe frames take milliseconds at least.
  ImageRgba8 moved = show(*viewer);
  for (int i = 0; i < 20 && moved.pixels == start.pixels; ++i) moved = show(*viewer);
  CHECK(moved.pixels != start.pixels);
}

TEST_CASE("view: F12 after a model switch saves a screenshot matching the headless render") {
  const TempDir dir;
  const std::string path = dir.file("shot.png");
  const auto viewer = openViewer(kSize, path);
  if (!viewer) return;
  viewer->handleKey(GLFW_KEY_M);
  show(*viewer);
  viewer->handleKey(GLFW_KEY_F12);
  checkMatches(pbr::readPng(path), headless(dir, kSize, {"--model", "blinn-phong"}));
}

TEST_CASE("view: a resized window rebuilds the G-buffer and the cluster grid, and nothing scene-sized") {
  const TempDir dir;
  const auto viewer = openViewer();
  if (!viewer) return;
  show(*viewer, 1);
  CHECK(viewer->frameSize() == kSize);
  const pbr::RendererCounters before = viewer->renderer().counters();
  CHECK(before.meshUploads > 0);
  CHECK(before.targetBuilds == 1);
  CHECK(before.programsCompiled > 0);
  // Through the window system, as a user's drag would: the framebuffer-size callback reaches the next frame.
  const glm::ivec2 resized{200, 120};
  glfwSetWindowSize(viewer->window().window(), resized.x, resized.y);
  for (int i = 0; i < 50 && viewer->frameSize() != resized; ++i) {
    glfwWaitEventsTimeout(0.05);
    viewer->frame();
  }
  REQUIRE(viewer->frameSize() == resized);
  const ImageRgba8 shown = show(*viewer);
  const pbr::ClusterConfig grid;
  const glm::uvec3 dims = viewer->renderer().clusters().dims();
  CHECK(dims.x == unsigned((resized.x + grid.tileSize - 1) / grid.tileSize));
  CHECK(dims.y == unsigned((resized.y + grid.tileSize - 1) / grid.tileSize));
  checkMatches(shown, headless(dir, resized));

  // The same path called directly, to a size no window manager would be asked for.
  viewer->resize(96, 200);
  checkMatches(show(*viewer), headless(dir, {96, 200}));
  // Two resizes: two new sets of targets, while no mesh or texture was uploaded and no program compiled again.
  const pbr::RendererCounters after = viewer->renderer().counters();
  CHECK(after.meshUploads == before.meshUploads);
  CHECK(after.textureUploads == before.textureUploads);
  CHECK(after.targetBuilds == before.targetBuilds + 2);
  CHECK(after.programsCompiled == before.programsCompiled);
}

TEST_CASE("view: pbr view --frames runs unattended and writes a screenshot matching pbr render") {
  const TempDir dir;
  const std::string shot = dir.file("s.png");
  const pbr::test::PbrRun run =
      runPbr(dir, {"view", "--frames", "10", "--size", "160x90", "--paused", "--screenshot", shot});
  if (run.exitCode == 3 && std::getenv("PBR_ALLOW_NO_GL") && std::strcmp(std::getenv("PBR_ALLOW_NO_GL"), "1") == 0) {
    MESSAGE("no window (" << run.err << "); allowed by PBR_ALLOW_NO_GL=1");
    return;
  }
  REQUIRE_MESSAGE(run.exitCode == 0, run.err);
  CHECK(run.out.find("wrote " + shot) != std::string::npos);
  checkMatches(pbr::readPng(shot), headless(dir, kSize, {}, "fxaa"));
}
