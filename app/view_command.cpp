#include <cstdio>
#include <filesystem>
#include <iostream>

#include "app/args.hpp"
#include "app/commands.hpp"
#include "app/option_table.hpp"
#include "app/common_options.hpp"
#include "app/file_clash.hpp"
#include "app/scene_source.hpp"
#include "app/viewer/viewer.hpp"
#include "core/io/image_output.hpp"

namespace pbr {

namespace {

// The viewer's keys, a line each, after the options.
std::string keysText() {
  std::string text = "\nkeys:\n";
  for (const KeyHelp& key : viewerKeys()) {
    const std::string keys = key.keys;
    text += "  " + keys + std::string(keys.size() < 14 ? 14 - keys.size() : 1, ' ') + key.action + "\n";
  }
  return text;
}

}  // namespace

int runView(const std::vector<std::string>& argv) {
  const auto& specs = commandOptions(Command::View);
  Args args(specs, argv);
  if (args.helpRequested()) {
    std::cout << Args::helpText("pbr view [options]",
                                "Opens a window (GLFW, OpenGL 4.5) rendering the scene continuously through the same "
                                "renderer as pbr render, under an overlay of per-pass frame times, light statistics "
                                "and controls.",
                                specs)
              << keysText();
    return 0;
  }
  ViewerOptions options;
  options.sceneName = args.get("--scene");
  options.sceneParams = sceneFileParams(args);
  // The viewer plays the animation --animation or --time chooses, from that time.
  options.sceneParams.gltfSelection.playable = options.sceneParams.gltfSelection.animated();
  options.sceneParams.defaultEnvironment = defaultEnvironment(args);
  applySceneShapeOptions(args, options.sceneParams);
  options.frame.model = parseShadingModel(args.get("--model"));
  options.frame.culling = parseCulling(args.get("--culling"));
  options.frame.aa = parseAntiAliasing(args.get("--aa"));
  options.frame.shadows = readShadowSettings(args);
  options.frame.transparency = readTransparency(args);
  options.frame.toneCurve = readToneCurve(args);
  options.size = args.getSize("--size");
  options.paused = args.has("--paused");
  const int frames = args.has("--quit-after") ? args.getInt("--quit-after", 1, 1 << 30) : 0;
  options.screenshot = args.get("--screenshot");
  if (!options.screenshot.empty()) ldrFileFormat(options.screenshot);
  options.screenshotOverlay = args.has("--screenshot-ui");
  options.overlay = !args.has("--no-ui");
  if (options.screenshotOverlay && !options.overlay) {
    throw UsageError("--screenshot-ui shows the overlay, which --no-ui hides");
  }
  options.environmentFolder = args.get("--env-dir");
  if (!options.environmentFolder.empty() && !std::filesystem::is_directory(options.environmentFolder)) {
    throw UsageError("--env-dir " + options.environmentFolder + ": not a folder");
  }
  options.timing = args.get("--timing");
  chooseTimingMode(options.timing, "");  // reject a bad mode before opening a window

  Scene scene = resolveScene(options.sceneName, options.sceneParams);
  applyEnvironmentOptions(args, scene);
  checkOutputsApart(sceneInputs(options.sceneName, scene), {{"--screenshot", options.screenshot}});
  applyCameraOption(args, scene);
  const ExposureChoice exposure = applyExposureOptions(args, scene);
  options.frame.exposure = exposure.exposure;
  options.frame.autoExposure = exposure.autoExposure;
  for (const std::string& note : scene.notes) std::printf("note: %s\n", note.c_str());
  if (!exposure.note.empty()) std::printf("note: %s\n", exposure.note.c_str());
  Viewer viewer(options, std::move(scene));
  std::printf("renderer: %s | %s | %s\n", viewer.window().info().renderer.c_str(),
              viewer.window().info().version.c_str(), viewer.window().info().platform.c_str());
  viewer.run(frames);
  return 0;
}

}  // namespace pbr
