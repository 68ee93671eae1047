// The interactive viewer, driven as a user would through its key handler, in a real GLFW window: these cases need
// a display and run under Xvfb (tests/under_xvfb.sh), in their own executable.
#include "app/viewer/viewer.hpp"

#include <GLFW/glfw3.h>
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "app/scene_source.hpp"
#include "app/viewer/environment_folder.hpp"
#include "core/scene/assets.hpp"
#include "core/scene/builtin_scenes.hpp"
#include "core/scene/exposure.hpp"
#include "core/scene/json_file.hpp"
#include "core/scene/scene_json.hpp"
#include "tests/cli_util.hpp"

using pbr::ImageRgba8;
using pbr::Viewer;
using pbr::test::runPbr;
using pbr::test::TempDir;

namespace {

constexpr glm::ivec2 kSize{160, 90};

// A paused viewer of a scene (the default one unless named), so that its lights stay where the headless render has
// them, with its overlay. Null (and the case failed, unless PBR_ALLOW_NO_GL=1) when no window can be opened.
std::unique_ptr<Viewer> openViewer(glm::ivec2 size = kSize, const std::string& screenshot = "",
                                   const std::string& sceneName = "default", const pbr::SceneParams& params = {}) {
  pbr::ViewerOptions options;
  options.size = size;
  options.screenshot = screenshot;
  options.paused = true;
  options.sceneName = sceneName;
  options.sceneParams = params;
  pbr::Scene scene = pbr::resolveScene(options.sceneName, options.sceneParams);
  options.frame.exposure = scene.displayExposure();
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

// A sun over a sphere on a floor, nothing else that lights, written into `dir`; returns the file's path.
std::string writeSunScene(const TempDir& dir) {
  const std::string scene = dir.file("sun.json");
  std::ofstream(scene) << R"({
    "camera": {"position": [0, 3, 6], "target": [0, 0.5, 0], "fov_y_deg": 50},
    "objects": [
      {"shape": "plane", "transform": {"scale": 8}, "material": {"base_color": [0.8, 0.8, 0.8], "roughness": 0.6}},
      {"shape": "sphere", "transform": {"translate": [0, 1, 0]},
       "material": {"base_color": [0.9, 0.3, 0.2], "roughness": 0.4}}
    ],
    "lights": [{"type": "directional", "direction": [-0.3, -1, -0.4], "illuminance_lux": 3}]
  })";
  return scene;
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
    const ImageRgba8 view = show(*viewer, 1);
    // The viewer's scene has no light that casts and no BLEND material: the shadows and transparency views, like the
    // cluster views without clustered culling, leave the final frame (the overlay says why).
    if (channel == pbr::DebugChannel::Shadows || channel == pbr::DebugChannel::Transparency) {
      CHECK(view.pixels == final.pixels);
      continue;
    }
    views.push_back(view);
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
  // Past the frames that time both assignment shapes (AssignShapeTrials), which compile the programs of both.
  show(*viewer, 6);
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

// `pbr view --quit-after 10 --paused` at `size` with `extra` arguments, writing its screenshot to `shot`; false when
// no window could be opened and PBR_ALLOW_NO_GL=1 allows that.
bool runView(const TempDir& dir, glm::ivec2 size, const std::string& shot, const std::vector<std::string>& extra) {
  const std::string sizeText = std::to_string(size.x) + "x" + std::to_string(size.y);
  std::vector<std::string> args = {"view",     "--quit-after", "10",  "--size", sizeText,
                                   "--paused", "--screenshot", shot};
  args.insert(args.end(), extra.begin(), extra.end());
  const pbr::test::PbrRun run = runPbr(dir, args);
  if (run.exitCode == 3 && std::getenv("PBR_ALLOW_NO_GL") && std::strcmp(std::getenv("PBR_ALLOW_NO_GL"), "1") == 0) {
    MESSAGE("no window (" << run.err << "); allowed by PBR_ALLOW_NO_GL=1");
    return false;
  }
  REQUIRE_MESSAGE(run.exitCode == 0, run.err);
  CHECK(run.out.find("wrote " + shot) != std::string::npos);
  return true;
}

TEST_CASE("view: pbr view --quit-after runs unattended and writes a screenshot matching pbr render") {
  const TempDir dir;
  // The screenshot is the frame alone whether the overlay is shown or hidden.
  for (const std::vector<std::string>& ui : {std::vector<std::string>{}, {"--no-ui"}}) {
    CAPTURE(ui.size());
    const std::string shot = dir.file("s.png");
    if (!runView(dir, kSize, shot, ui)) return;
    checkMatches(pbr::readPng(shot), headless(dir, kSize, {}, "fxaa"));
  }
}

TEST_CASE("view: an unattended run whose screenshot cannot be written exits 1 naming it") {
  const TempDir dir;
  // The frame alone, and the window with its overlay (written while the last frame presents).
  for (const std::vector<std::string>& ui : {std::vector<std::string>{}, {"--screenshot-ui"}}) {
    CAPTURE(ui.size());
    std::vector<std::string> args = {"view", "--quit-after", "2", "--size", "64x36", "--screenshot", "/dev/full"};
    args.insert(args.end(), ui.begin(), ui.end());
    const pbr::test::PbrRun run = runPbr(dir, args);
    if (run.exitCode == 3) return;  // no window: the other cases say so
    CHECK(run.exitCode == 1);
    CHECK(run.err == "pbr view: /dev/full: cannot write: No space left on device\n");
  }
}

TEST_CASE("view: --screenshot-ui shows the overlay's panels at the top corners and the frame between them") {
  const TempDir dir;
  const glm::ivec2 size{960, 400};
  const std::string frame = dir.file("frame.png"), window = dir.file("window.png");
  if (!runView(dir, size, frame, {"--no-ui"}) || !runView(dir, size, window, {"--screenshot-ui"})) return;
  const ImageRgba8 a = pbr::readPng(frame), b = pbr::readPng(window);
  REQUIRE(a.width == b.width);
  REQUIRE(a.height == b.height);
  const auto region = [](const ImageRgba8& image, int x0, int x1, int y0, int y1) {
    ImageRgba8 part;
    part.width = x1 - x0;
    part.height = y1 - y0;
    for (int y = y0; y < y1; ++y) {
      const auto row = image.pixels.begin() + (std::ptrdiff_t(y) * image.width + x0) * 4;
      part.pixels.insert(part.pixels.end(), row, row + std::ptrdiff_t(part.width) * 4);
    }
    return part;
  };
  // The panels are 380 pixels wide, 8 from the edges: between them the frame is untouched, under them their
  // backgrounds, text and graph replace the scene.
  CHECK(region(a, 400, 560, 0, size.y).pixels == region(b, 400, 560, 0, size.y).pixels);
  CHECK(compare(region(a, 8, 388, 8, 100), region(b, 8, 388, 8, 100)).mean > 10.0);
  CHECK(compare(region(a, 572, 952, 8, 100), region(b, 572, 952, 8, 100)).mean > 10.0);
}

TEST_CASE("view: the overlay runs, graphs every pass and takes the model and culling through the viewer's handlers") {
  const auto viewer = openViewer();
  if (!viewer) return;
  REQUIRE(viewer->overlay() != nullptr);
  const ImageRgba8 pbrClustered = show(*viewer, 10);
  CHECK(viewer->framesRendered() == 10);
  const pbr::PassHistory& history = viewer->passHistory();
  CHECK(!history.frames().empty());
  CHECK(history.frames().size() <= 10);
  for (const char* pass : {"gbuffer", "cluster", "lighting"}) {
    CAPTURE(pass);
    CHECK(std::find(history.names().begin(), history.names().end(), pass) != history.names().end());
  }
  CHECK(viewer->lightStats().lights == 256);
  CHECK(viewer->lightStats().clusters > 0);

  // The handlers the overlay's radio buttons and combos call, as the keys do.
  viewer->setCulling(pbr::Culling::None);
  CHECK(std::string(toString(viewer->frameOptions().culling)) == "none");
  CHECK(show(*viewer).pixels == pbrClustered.pixels);
  viewer->setModel(pbr::ShadingModel::BlinnPhong);
  CHECK(std::string(toString(viewer->frameOptions().model)) == "blinn-phong");
  CHECK(compare(show(*viewer), pbrClustered).mean > 5.0);
  viewer->setModel(pbr::ShadingModel::Pbr);
  viewer->setCulling(pbr::Culling::Clustered);
  CHECK(show(*viewer).pixels == pbrClustered.pixels);
  // Brute force has no clusters to count.
  viewer->setCulling(pbr::Culling::None);
  show(*viewer, 1);
  CHECK(viewer->lightStats().clusters == 0);
  viewer->setCulling(pbr::Culling::Clustered);

  viewer->setVariant(pbr::parseShadingVariant("ndf=beckmann"));
  CHECK(show(*viewer).pixels != pbrClustered.pixels);
  viewer->setVariant({});
  CHECK(show(*viewer).pixels == pbrClustered.pixels);

  // The overlay's time graph counts a pass once per frame and never more than its window.
  for (int i = 0; i < 5; ++i) viewer->frame();
  CHECK(viewer->passHistory().frames().size() <= pbr::PassHistory::kFrames);
  // What the pass history's last frame holds: each pass at most once.
  const auto& last = viewer->passHistory().frames().back().passes;
  for (size_t i = 0; i < last.size(); ++i) {
    for (size_t j = i + 1; j < last.size(); ++j) CHECK(last[i].first != last[j].first);
  }
}

TEST_CASE("view: the overlay offers the lobes of the extensions the scene uses, each switched off through the viewer") {
  const auto viewer = openViewer(kSize, "", "materials");
  if (!viewer) return;
  // The strip uses ior, clearcoat, sheen and transmission; the default scene none of them.
  const pbr::MaterialLobes& used = viewer->usedLobes();
  CHECK(used.specular);
  CHECK(used.clearcoat);
  CHECK(used.sheen);
  CHECK(used.transmission);
  const pbr::MaterialLobes none = pbr::usedLobes(pbr::makeBuiltinScene("default"));
  CHECK_FALSE((none.specular || none.clearcoat || none.sheen || none.transmission));
  const ImageRgba8 all = show(*viewer);
  for (const auto off : {&pbr::MaterialLobes::specular, &pbr::MaterialLobes::clearcoat, &pbr::MaterialLobes::sheen,
                         &pbr::MaterialLobes::transmission}) {
    pbr::MaterialLobes lobes;
    lobes.*off = false;
    viewer->setLobes(lobes);
    CHECK_FALSE(viewer->lobes().*off);
    CHECK(show(*viewer).pixels != all.pixels);  // the lobe's sphere changes
    viewer->setLobes({});
  }
  CHECK(show(*viewer).pixels == all.pixels);
}

TEST_CASE("view: a scene saved from the viewer renders headless as the viewer shows it") {
  const TempDir dir;
  const auto viewer = openViewer();
  if (!viewer) return;
  viewer->orbit(0.6f, -0.2f);
  viewer->zoom(0.8f);
  viewer->setExposure(viewer->frameOptions().exposure * 1.5f);
  viewer->setLightCount(64);
  const ImageRgba8 shown = show(*viewer);
  const std::string saved = dir.file("saved.json");
  viewer->saveScene(saved);

  const pbr::Scene reread = pbr::loadSceneFile(saved);
  const pbr::Camera& c = viewer->camera().camera();
  for (int i = 0; i < 3; ++i) {
    CHECK(reread.camera.position[i] == doctest::Approx(c.position[i]).epsilon(1e-6));
    CHECK(reread.camera.target[i] == doctest::Approx(c.target[i]).epsilon(1e-6));
  }
  CHECK(reread.camera.fovYDeg == c.fovYDeg);
  CHECK(reread.displayExposure() == doctest::Approx(viewer->frameOptions().exposure).epsilon(1e-6));
  CHECK(reread.lights.size() == 64);
  // The scene's generator stays a generator: its count changes, its lights are not listed.
  const nlohmann::json document = pbr::readJsonFile(saved);
  CHECK(document["random_lights"]["count"] == 64);
  CHECK(document.value("lights", nlohmann::json::array()).size() < 8);
  checkMatches(shown, headless(dir, kSize, {"--scene", saved}));
}

TEST_CASE("view: a built-in's own light rule is saved as its lights, and the saved scene renders the same") {
  const TempDir dir;
  pbr::SceneParams params;
  params.lights = 8;  // sphere-grid's rule: random lights in place of its four corner lights
  const auto viewer = openViewer(kSize, "", "sphere-grid", params);
  if (!viewer) return;
  const ImageRgba8 shown = show(*viewer);
  const std::string saved = dir.file("grid.json");
  viewer->saveScene(saved);
  const pbr::Scene reread = pbr::loadSceneFile(saved);
  CHECK(reread.lights.size() == 8);
  checkMatches(shown, headless(dir, kSize, {"--scene", saved}));
}

TEST_CASE("view: a glTF model given alone is saved as a scene placing it, and renders the same") {
  const TempDir dir;
  const auto viewer = openViewer(kSize, "", pbr::assetPath("BoxTextured/glTF-Embedded/BoxTextured.gltf"));
  if (!viewer) return;
  viewer->orbit(-0.5f, 0.3f);
  const ImageRgba8 shown = show(*viewer);
  const std::string saved = dir.file("box.json");
  viewer->saveScene(saved);
  const pbr::Scene reread = pbr::loadSceneFile(saved);
  CHECK(reread.gltfFiles.size() == 1);
  CHECK(reread.environment.has_value());  // the sky the model was given, written out
  checkMatches(shown, headless(dir, kSize, {"--scene", saved}));
}

TEST_CASE("view: the environment picker lists .hdr files and its choice relights the frame") {
  const TempDir dir;
  for (const char* name : {"b.hdr", "a.HDR", "notes.txt"}) std::ofstream(dir.file(name)) << "not an image";
  std::filesystem::create_directory(dir.file("folder.hdr"));
  const std::vector<std::string> files = pbr::hdrFiles(dir.file(""));
  REQUIRE(files.size() == 2);
  CHECK(std::filesystem::path(files[0]).filename() == "a.HDR");
  CHECK(std::filesystem::path(files[1]).filename() == "b.hdr");
  CHECK(pbr::environmentFolder("", std::nullopt).find("environments") != std::string::npos);

  const auto viewer = openViewer();
  if (!viewer) return;
  const ImageRgba8 unlit = show(*viewer);
  CHECK(viewer->setEnvironment("sky").empty());
  REQUIRE(viewer->scene().environment.has_value());
  CHECK(compare(show(*viewer), unlit).mean > 2.0);
  // A file that is no image keeps the sky, and says why naming it.
  const std::string message = viewer->setEnvironment(files[1]);
  CHECK(message.find("b.hdr") != std::string::npos);
  CHECK(viewer->scene().environment.has_value());
  CHECK(viewer->scene().environment->file.empty());
  CHECK(viewer->setEnvironment("none").empty());
  CHECK_FALSE(viewer->scene().environment.has_value());
  CHECK(show(*viewer).pixels == unlit.pixels);
}

TEST_CASE("view: a scene's directional light stays lit through animated frames") {
  const TempDir dir;
  // A sun and nothing else that lights: animating the point lights must leave the sun as the scene has it.
  const std::string scene = writeSunScene(dir);
  const auto viewer = openViewer(kSize, "", scene);
  if (!viewer) return;
  viewer->setPaused(false);
  const ImageRgba8 shown = show(*viewer, 10);
  const ImageRgba8 rendered = headless(dir, kSize, {"--scene", scene});
  // Lit: the sun reaches the floor (a frame without it is black, there being no other light).
  double sum = 0.0;
  for (size_t i = 0; i < shown.pixels.size(); i += 4) sum += shown.pixels[i + 1];
  CHECK(sum / double(shown.pixels.size() / 4) > 20.0);
  checkMatches(shown, rendered);
}

TEST_CASE("view: the overlay's shadow settings reach the frame, and the shadows debug view shows them") {
  const TempDir dir;
  const std::string scene = writeSunScene(dir);
  const auto viewer = openViewer(kSize, "", scene);
  if (!viewer) return;
  const ImageRgba8 shadowed = show(*viewer);
  checkMatches(shadowed, headless(dir, kSize, {"--scene", scene}));
  pbr::ShadowSettings settings = viewer->frameOptions().shadows;
  settings.mode = pbr::ShadowMode::None;
  viewer->setShadows(settings);
  const ImageRgba8 plain = show(*viewer);
  checkMatches(plain, headless(dir, kSize, {"--scene", scene, "--shadows", "none"}));
  CHECK(compare(plain, shadowed).mean > 0.5);  // the sphere's shadow on the floor is gone
  settings.mode = pbr::ShadowMode::Auto;
  settings.filter = pbr::ShadowFilter::Hard;
  settings.atlasSize = 1024;
  viewer->setShadows(settings);
  checkMatches(show(*viewer),
               headless(dir, kSize, {"--scene", scene, "--shadow-filter", "hard", "--shadow-atlas", "1024"}));
  viewer->setView(pbr::DebugChannel::Shadows);
  checkMatches(show(*viewer), headless(dir, kSize, {"--scene", scene, "--shadow-filter", "hard", "--shadow-atlas",
                                                    "1024", "--debug", "shadows"}));
}

// The frame of `path` loaded posed at `time` (as `pbr render --animation 0 --time` loads it), seen with the camera and
// exposure of the model's first moment, and lit by that moment's default rig where the file has no lights: the
// viewer keeps what it framed the model with as the animation plays.
ImageRgba8 loadedAt(const std::string& path, double time) {
  pbr::ViewerOptions options;
  options.size = kSize;
  options.paused = true;
  options.sceneParams.gltfSelection.animation = "0";
  const pbr::Scene first = pbr::resolveScene(path, options.sceneParams);
  options.sceneParams.gltfSelection.time = time;
  pbr::Scene scene = pbr::resolveScene(path, options.sceneParams);
  scene.camera = first.camera;
  if (!first.gltfPlacedLights) {
    scene.lights = first.lights;
    scene.directionalLights = first.directionalLights;
  }
  options.frame.exposure = first.displayExposure();
  Viewer viewer(options, std::move(scene));
  return show(viewer);
}

TEST_CASE("view: --animation plays the glTF animation, each moment the frame the file posed there gives") {
  // A morph-target animation, a skeleton's and one that turns spot lights (Blender and Babylon for 3ds Max).
  for (const char* file : {"exports/blender-01_morphed_cube/01_morphed_cube.gltf",
                           "exports/blender-03_skinned_cylinder/03_skinned_cylinder.gltf",
                           "exports/babylon-max-AnimatedSpotlights/AnimatedSpotlights.gltf"}) {
    CAPTURE(file);
    const std::string path = pbr::assetPath(file);
    if (!std::filesystem::exists(path)) {
      MESSAGE("shared export not found: " << path << ": skipped");
      continue;
    }
    // Each window in turn: the references first, then the viewer that plays.
    const std::vector<double> times = {0.7, 1.6};
    std::vector<ImageRgba8> expected;
    for (const double time : times) expected.push_back(loadedAt(path, time));
    pbr::SceneParams params;
    params.gltfSelection.animation = "0";
    params.gltfSelection.playable = true;
    const auto viewer = openViewer(kSize, "", path, params);
    if (!viewer) return;
    REQUIRE(viewer->playsAnimation());
    CHECK(viewer->animationDuration() > 1.0);
    ImageRgba8 previous = show(*viewer);
    for (size_t i = 0; i < times.size(); ++i) {
      CAPTURE(times[i]);
      viewer->setAnimationTime(times[i]);
      const ImageRgba8 shown = show(*viewer);
      CHECK(shown.pixels != previous.pixels);
      checkMatches(shown, expected[i]);
      previous = shown;
    }
    // Playing, the frames move on; a whole animation's length later, the same moment.
    viewer->setAnimationTime(1.6 + viewer->animationDuration());
    CHECK(viewer->animationTime() == doctest::Approx(1.6).epsilon(1e-6));
    CHECK(show(*viewer).pixels == previous.pixels);
    viewer->handleKey(GLFW_KEY_P);
    ImageRgba8 moved = show(*viewer);
    for (int i = 0; i < 20 && moved.pixels == previous.pixels; ++i) moved = show(*viewer);
    CHECK(moved.pixels != previous.pixels);
  }
}

TEST_CASE("view: T steps through the tone curves, each frame the one pbr render --tonemap gives") {
  const TempDir dir;
  const auto viewer = openViewer();
  if (!viewer) return;
  const ImageRgba8 hill = show(*viewer);
  viewer->handleKey(GLFW_KEY_T);
  CHECK((viewer->frameOptions().toneCurve == pbr::ToneCurve::AcesNarkowicz));
  viewer->handleKey(GLFW_KEY_T);
  CHECK((viewer->frameOptions().toneCurve == pbr::ToneCurve::KhronosNeutral));
  const ImageRgba8 neutral = show(*viewer);
  CHECK(neutral.pixels != hill.pixels);
  checkMatches(neutral, headless(dir, kSize, {"--tonemap", "khronos-neutral"}));
  for (size_t i = 2; i < std::size(pbr::kToneCurves); ++i) viewer->handleKey(GLFW_KEY_T);
  CHECK((viewer->frameOptions().toneCurve == pbr::ToneCurve::AcesHill));  // round again
}

TEST_CASE("view: X meters the exposure as pbr render --exposure auto does, and + or - fixes it again") {
  const TempDir dir;
  const auto viewer = openViewer();
  if (!viewer) return;
  viewer->handleKey(GLFW_KEY_X);
  CHECK(viewer->frameOptions().autoExposure);
  // The first frame converges at once; the same view then meters the same, so the frames after it hold.
  const ImageRgba8 metered = show(*viewer, 8);
  checkMatches(metered, headless(dir, kSize, {"--exposure", "auto"}));
  REQUIRE(viewer->meteredExposure());
  const float shown = viewer->frameOptions().exposure;
  CHECK(shown == doctest::Approx(pbr::exposureFromEv100(viewer->meteredExposure()->ev100)));
  viewer->handleKey(GLFW_KEY_EQUAL);
  CHECK_FALSE(viewer->frameOptions().autoExposure);
  CHECK(viewer->frameOptions().exposure > shown);
}
