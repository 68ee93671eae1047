#include <cstdio>
#include <iostream>

#include "app/args.hpp"
#include "app/commands.hpp"
#include "app/scene_source.hpp"
#include "app/viewer/viewer.hpp"
#include "core/image.hpp"

namespace pbr {

namespace {

const std::vector<OptionSpec>& viewOptions() {
  static const std::vector<OptionSpec> specs = {
      {"--scene", "NAME|FILE", "built-in scene or scene file, as for pbr render (default: default)"},
      {"--lights", "N", "number of point lights (default: the scene's)"},
      {"--view-angle", "DEG", "fresnel-floor: angle between the floor normal and the view (default 40)"},
      spotShareOption(),
      {"--model", "MODEL", "shading model at start: pbr (default) or blinn-phong (key M switches)"},
      {"--culling", "C", "clustered (default) or none at start (key C switches)"},
      {"--aa", "none|fxaa", "anti-aliasing of the shown frame and screenshots, after tone mapping (default fxaa)"},
      {"--exposure", "X", "exposure multiplier at start (default: the scene's; keys + and -)"},
      ev100Option(),
      cameraOption(),
      environmentOption(),
      environmentIntensityOption(),
      {"--size", "WxH", "window size in pixels (default 1280x720)"},
      {"--paused", "", "start with the light animation paused (key P toggles)"},
      {"--frames", "K", "exit after K frames, writing --screenshot if given (for unattended runs)"},
      {"--screenshot", "F.png", "where F12 and the end of a --frames run save the frame"},
      {"--timing", "MODE", "auto (default), gpu (timer queries) or serial (glFinish + CPU clock)"},
      allowOutsideUrisOption(),
      strictOption(),
  };
  return specs;
}

std::string keysHelp() {
  return "\nkeys: drag to orbit, scroll to zoom, W/A/S/D/Q/E fly, M Blinn-Phong/PBR, C clustered/brute force,\n"
         "V debug view (final, then " + debugChannelNames(", ") + "),\n"
         "+/- exposure, [/] halve/double the lights, P pause the lights, F12 screenshot, Esc quit\n";
}

}  // namespace

int runView(const std::vector<std::string>& argv) {
  const auto& specs = viewOptions();
  Args args(specs, argv);
  if (args.helpRequested()) {
    std::cout << Args::helpText("pbr view [options]",
                                "Opens a window (GLFW, OpenGL 4.5) rendering the scene continuously through the same "
                                "renderer as pbr render, with live pass timings in the title.",
                                specs)
              << keysHelp();
    return 0;
  }
  ViewerOptions options;
  options.sceneName = args.get("--scene", "default");
  options.sceneParams = sceneFileParams(args);
  options.sceneParams.defaultEnvironment = defaultEnvironment(args);
  if (args.has("--lights")) options.sceneParams.lights = args.getInt("--lights", 0, 0, 1 << 20);
  if (args.has("--view-angle")) options.sceneParams.viewAngleDeg = args.getFloat("--view-angle", 40.0f, 0.0f, 89.0f);
  options.frame.model = parseShadingModel(args.get("--model", "pbr"));
  options.frame.culling = parseCulling(args.get("--culling", "clustered"));
  options.frame.aa = parseAntiAliasing(args.get("--aa", "fxaa"));
  options.size = args.getSize("--size", options.size);
  options.paused = args.has("--paused");
  const int frames = args.getInt("--frames", 0, 1, 1 << 30);
  options.screenshot = args.get("--screenshot", "");
  if (!options.screenshot.empty()) requirePngPath(options.screenshot);
  options.timing = args.get("--timing", "auto");
  chooseTimingMode(options.timing, "");  // reject a bad mode before opening a window

  Scene scene = resolveScene(options.sceneName, options.sceneParams);
  applyEnvironmentOptions(args, scene);
  applyCameraOption(args, scene);
  options.frame.exposure = applyExposureOptions(args, scene);
  for (const std::string& note : scene.notes) std::printf("note: %s\n", note.c_str());
  Viewer viewer(options, std::move(scene));
  std::printf("renderer: %s | %s | %s\n", viewer.window().info().renderer.c_str(),
              viewer.window().info().version.c_str(), viewer.window().info().platform.c_str());
  viewer.run(frames);
  return 0;
}

}  // namespace pbr
