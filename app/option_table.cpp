#include "app/option_table.hpp"

#include <algorithm>
#include <map>
#include <optional>
#include <stdexcept>

#include "app/accuracy/accuracy_variants.hpp"
#include "app/accuracy/pair_cost.hpp"
#include "app/accuracy/shadow_rows.hpp"
#include "app/accuracy/transparency_rows.hpp"
#include "app/bench/bench_sweep.hpp"
#include "app/scene_source.hpp"
#include "app/viewer/viewer.hpp"
#include "core/io/context_info.hpp"
#include "core/scene/tone_curve.hpp"
#include "debug/debug_channel.hpp"
#include "post/fxaa_pass.hpp"
#include "reference/brdf_form_names.hpp"
#include "reference/reference_renderer.hpp"
#include "renderer/renderer.hpp"

namespace pbr {

namespace {

template <typename T, typename Text>
std::string listText(const std::vector<T>& items, Text text) {
  std::string out;
  for (const T& item : items) out += (out.empty() ? "" : ",") + std::string(text(item));
  return out;
}

std::string ladderNames() {
  std::string names;
  for (const AccuracyVariant& v : accuracyLadder()) names += (names.empty() ? "" : ", ") + v.name;
  return names;
}

std::vector<OptionSpec> makeTable() {
  const FrameOptions frame;
  const RendererConfig renderer;
  const ShadowSettings shadows;
  const PairCostSettings pairCost;
  const reference::ReferenceOptions referenceDefaults;
  return {
      // The scene and its lights.
      {"--scene", "NAME|FILE", "built-in scene (" + builtinSceneList() + ") or scene file (.json, .gltf, .glb)",
       "default", ""},
      {"--lights", "N", "number of point lights", "", "the scene's; 256 for default"},
      {"--view-angle", "DEG", "fresnel-floor: angle between the floor normal and the view", "",
       "as the scene file places it, 40"},
      {"--spot-share", "F", "make this share (0-1) of a scene's random lights spot lights, aimed down at random with "
                            "outer angles of 10-60 degrees", "", "the scene's, 0"},
      {"--camera", "N|auto",
       "view through the scene's glTF camera N (from 0, in node order) or, for a model given alone, auto: framed to "
       "its bounds", "", "the scene file's camera; a model's first camera, else auto"},
      {"--environment", "F.hdr|F.exr|sky|none",
       "image-based lighting (PBR) and background from a Radiance .hdr or OpenEXR .exr picture or the procedural "
       "sky, or none, replacing the scene's environment", "",
       "the scene file's; a glTF model, or a scene file that places models and has no \"environment\", gets the "
       "sky"},
      {"--environment-intensity", "X", "radiance multiplier of the environment", "", "the scene's, 1"},
      {"--allow-outside-uris", "",
       "let glTF models read buffers and images outside their own folder (refused by default)"},
      {"--strict", "", "refuse a scene file holding a key the reader does not know (a misspelt field), and a glTF "
                       "file deviating from the specification where viewers read it anyway (a byteStride of 0), "
                       "instead of warning about it"},
      {"--gltf-scene", "N", "draw scene N (from 0) of glTF files that hold several", "",
       "the file's default scene (its \"scene\"), else its first"},
      {"--animation", "NAME|INDEX", "pose glTF models by this animation (its name, or its index from 0), at --time",
       "", "none: the rest pose, nodes as the file places them; the first animation where only --time is given"},
      {"--time", "SECONDS",
       "the time of the --animation glTF models are posed at, sampled as the file interpolates it (step, linear, "
       "cubic spline; the ends hold outside its keyframes)", "", "0 with --animation; none without: the rest pose"},

      // Shading.
      {"--model", "MODEL", "shading model: pbr or blinn-phong", toString(frame.model), ""},
      {"--visibility", "V", "PBR Smith visibility: exact (height-correlated), hammon or separable", "",
       std::string(toString(frame.variant.visibility)) + ", or --variant's"},
      {"--variant", "K=V,...|study",
       "shading variant, PBR: visibility=exact|hammon|separable, ndf=ggx|beckmann, fresnel=schlick|exact|schlick-sg, "
       "diffuse=lambert-1-f|lambert|burley|lambert-1-f-vh; or, alone, study: the PBR model of the "
       "Blinn-Phong-vs-PBR study, GGX, Hammon's visibility, Schlick Fresnel and Lambert weighted by (1 - F(v.h)); "
       "Blinn-Phong: lobe=pow or sg, the lobe's spherical-Gaussian fit (one exp2 instead of pow); the CPU "
       "reference evaluates the PBR terms but ndf=beckmann and diffuse=burley", "",
       toString(frame.variant) + "," + toString(frame.variant.lobe)},
      {"--hdr-format", "F", "HDR radiance target: rgba16f, r11g11b10f or rgba32f", toString(renderer.hdrFormat), ""},
      {"--gbuffer", "P", "G-buffer precision: lean (16 bytes per pixel) or float (unquantised, 44 bytes)",
       toString(renderer.gbuffer), ""},

      // Culling.
      {"--culling", "C",
       "clustered, none (brute force: every light for every pixel) or auto (per frame, whichever the times "
       "measured here predict cheaper)", toString(kCommandCulling), ""},
      {"--tile", "auto|PX",
       "cluster screen-tile side in pixels, or auto: " + std::to_string(renderer.clusters.tileSize) +
           ", and half of it timed against it where lists are long, keeping the faster on this machine",
       "auto", ""},
      {"--slices", "S", "cluster depth slices, exponential between near and far",
       std::to_string(renderer.clusters.slices), ""},
      {"--assign-shape", "auto|invocation|workgroup|cluster",
       "how the clustered light assignment spreads its work: four lights and one list per invocation (llvmpipe's "
       "shape), a workgroup per light and per list (a GPU's for few large lights), an invocation per cluster testing "
       "batches of lights and a workgroup per list (a GPU's for few lights and clusters), or per pass the one the "
       "frames after a light count's first time fastest on this machine",
       toString(renderer.clusters.lightPass), ""},

      // Shadows and transparency.
      {"--shadows", "none|on|auto",
       "which lights cast shadows: auto as the scene says (glTF lights, JSON spot and directional lights, and "
       "those with \"shadows\": true), on every light, none", toString(shadows.mode), ""},
      {"--shadow-filter", "F",
       "shadow-map filter: hard (one comparison), pcf3x3 (3x3 bilinear comparisons, a 4x4-texel tent) or "
       "poisson16 (16 bilinear comparisons on a 1.5-texel disc)", toString(shadows.filter), ""},
      {"--shadow-atlas", "SIZE",
       "side of the shadow atlas in texels, a power of two from 256 to 16384 (4 bytes a texel: 4096 is 64 MiB, "
       "8192 256 MiB); allocated only when a light casts", std::to_string(shadows.atlasSize), ""},
      {"--shadow-draws", "auto|per-view|per-light",
       "how the shadow casters are drawn, the same depths either way: a draw per caster and view, or per caster and "
       "run of a light's views with each view's viewport chosen in the vertex shader (fewer draws to record; needs "
       "GL_ARB_shader_viewport_layer_array), or per-light on a GPU that has it and per-view on a CPU rasterizer",
       toString(shadows.draws), ""},
      {"--shadow-cache", "on|off",
       "keep shadow maps from frame to frame: a still frame keeps them all (camera, frame size, lights, poses, "
       "cluster grid and atlas unchanged), and while the camera or a light moves a view whose light, square and "
       "casters are unchanged keeps its depths; off draws every map every frame",
       shadows.cache ? "on" : "off", ""},
      {"--transparency", "T",
       "how BLEND materials composite: sorted (back to front by their bounds, Porter-Duff over), oit (weighted "
       "blended order-independent transparency, one pass in any order; 18 bytes per pixel) or exact (every "
       "fragment in a list per pixel, composited in depth order; room for 8 a pixel, 132 bytes per pixel)",
       toString(Transparency::Sorted), ""},

      // The display image.
      {"--tonemap", "CURVE",
       std::string("the PBR display transform's tone curve after exposure: ") + toneCurveNames() +
           " (aces-hill: Hill's ACES fit, the study's curve; aces-narkowicz: Narkowicz's fit; khronos-neutral: "
           "Khronos PBR Neutral, glTF-Sample-Viewer's default; agx: Blender's AgX Base; reinhard: white point "
           "4; exponential: 1 - e^-x, the seeds'; linear: a clamp)",
       toString(ToneCurve::AcesHill), ""},
      {"--exposure", "X|auto",
       "exposure multiplier before the tone curve, or auto (GPU frames): metered from the frame itself (the mean "
       "log2 luminance between its 10th and 90th percentiles shown as 0.18), reported as EV100, the viewer adapting "
       "to it 3 EV per second brighter and 1 darker; a scene camera's exposure keeps priority", "", "the scene's, 1"},
      {"--ev100", "EV",
       "physical exposure: the camera's exposure value at ISO 100 (sunny day about 15, indoors 6-8), scaling "
       "radiance by 1 / (1.2 2^EV) before --exposure", "",
       "the scene camera's; for a glTF model given alone with lights, what an incident-light meter reads at the "
       "model; else none"},
      {"--aa", "none|fxaa",
       "anti-aliasing of the display image (PNGs, the viewer's frame and screenshots), after tone mapping: FXAA 3.11 "
       "or none; --hdr captures are never filtered", toString(kDisplayAntiAliasing), ""},
      {"--debug", "CHANNEL",
       "a debug channel with its legend in place of the frame: " + debugChannelNames() +
           " (efficiency: contributing / evaluated light-pixel pairs per pixel; shadows: the light casting lights "
           "bring over what they would unshadowed, 0 black, with the shadow atlas inset; clusters and slices need "
           "--culling clustered)",
       "", "none, the frame itself"},
      {"--size", "WxH", "frame size in pixels (the viewer's window)", sizeText({1280, 720}), ""},

      // Timing and counting.
      {"--warmup", "K",
       "untimed warm-up frames before the timed ones, more while a cluster's light list does not fit yet (pbr "
       "render: after the first frame; pbr bench: per configuration, at least 1, the first estimating its time)",
       "2", ""},
      {"--frames", "K", "timed frames (per configuration of a sweep or an experiment): medians and spreads are taken "
                        "over them", "5", ""},
      {"--stats", "",
       "count light statistics on the GPU (visible lights, culling efficiency) in an untimed extra frame"},
      {"--timing", "MODE", "auto (serial on a CPU rasterizer, else gpu), gpu (timer queries) or serial (glFinish "
                           "+ CPU clock)", "auto", ""},
      {"--egl-platform", "P", "auto, surfaceless (Mesa) or device (first hardware device)",
       toString(EglPlatform::Auto), ""},
      {"--capture-frame", "K",
       "mark the K-th frame rendered for graphics debuggers, counting from 1 over every frame of the run (the first, "
       "the warm-up, the timed ones and the final capture frame, 1 to --warmup + --frames + 2): captured through "
       "RenderDoc's in-application API when run under RenderDoc (renderdoccmd capture ...), and always wrapped in a "
       "debug group and marker 'capture frame K'", "", "none"},

      // Sweeps and measurements.
      {"--max-seconds", "S", "skip a configuration estimated (first warm-up frame x its frames) to take over S seconds",
       numberText(BenchSettings{}.maxSeconds), ""},
      {"--constant-density", "",
       "scale light radii by sqrt(L0/lights), L0 the smallest of --lights, holding lights x radius^2 (the light "
       "density) constant"},
      {"--shard", "K/N",
       "measure only the K-th of N disjoint parts of the sweep (1 <= K <= N), for N processes or machines; "
       "pbr bench-merge joins their --json reports", "", "the whole sweep"},
      {"--allow-mixed", "",
       "merge shards measured on different renderers or builds (or, with a CPU rasterizer, CPUs); by default they "
       "are refused, their times not being comparable"},
      {"--pair-cost", "LIST",
       "instead of the sweep, measure ns per light-pixel pair of these accuracy-ladder variants (or all) with "
       "brute force, lights reaching every pixel, at --size"},
      {"--pair-materials", "LIST",
       "comma-separated materials of the cost-per-pair fixture, each variant timed on each: core, specular "
       "(KHR_materials_ior and _specular), clearcoat (KHR_materials_clearcoat), sheen (KHR_materials_sheen)",
       "core", ""},
      {"--pair-lights", "N", "lights reaching every pixel in the cost-per-pair measurement (with --pair-scene, the "
       "scene's random lights)", std::to_string(pairCost.lights), ""},
      {"--pair-scene", "NAME|FILE",
       "measure the cost per pair on this scene instead of the fixture, each variant brute force and clustered, "
       "per pair its frame evaluates (its lighting pass's per-pixel work included, as its frames pay it)", "",
       "the fixture"},
      {"--pair-size", "WxH", "frame size of the cost-per-pair measurement", sizeText(pairCost.size), ""},
      {"--rounds", "R",
       "timing rounds, each timing every variant (and in pbr accuracy then every shadow row, then every "
       "transparency row) once, in turn", std::to_string(pairCost.rounds), ""},
      {"--scenes", "LIST",
       "comma-separated scenes of analytic shapes; fresnel-floor:DEG sets the view angle; textures are removed",
       "sphere-grid,fresnel-floor:0,fresnel-floor:40,fresnel-floor:65,fresnel-floor:80,material-specular,"
       "material-clearcoat,material-sheen,material-transmission", ""},
      {"--variants", "LIST", "comma-separated variants or all: " + ladderNames(), "all", ""},
      {"--no-cost", "",
       "skip the timings: cost per pair and the shadow and transparency rows' pass times (the chart needs them)"},
      {"--shadow-rows", "LIST",
       "shadow settings measured on --shadow-scene with the exact variant: unshadowed, FILTER or FILTER:ATLAS "
       "(hard, pcf3x3, poisson16; a power-of-two atlas, 256 to 16384, else 4096), or none",
       kDefaultShadowRows, ""},
      {"--shadow-scene", "NAME", "the shadow rows' scene, built-in or a file; its lights cast as it says",
       "shadow-trio", ""},
      {"--shadow-cost-size", "WxH", "frame size at which the shadow rows' shadow and lighting passes are timed",
       sizeText({640, 360}), ""},
      {"--transparency-rows", "LIST",
       "orderings of BLEND surfaces measured on --transparency-scene with the exact variant and no shadows: sorted, "
       "oit, exact, or none",
       kDefaultTransparencyRows, ""},
      {"--transparency-scene", "NAME", "the transparency rows' scene, built-in or a file, with BLEND materials",
       "transparency", ""},
      {"--transparency-cost-size", "WxH",
       "frame size at which the transparency rows' transparency pass and frame are timed", sizeText({640, 360}), ""},
      {"--brdf-slices", "", "also write per-variant BRDF error slices over (n.v angle) x (roughness)"},
      {"--brdf-slice-size", "AxR", "BRDF slice grid: view angles x roughness values", sizeText({90, 64}), ""},
      {"--threads", "N", "CPU reference worker threads, 0 for every hardware thread",
       std::to_string(referenceDefaults.threads), ""},
      {"--geometry", "G", "meshes (the triangles the GPU rasterizes) or analytic (the exact shapes)",
       toString(referenceDefaults.geometry), ""},

      // Outputs.
      {"--out", "F.png|F.jpg", "write the 8-bit sRGB display image as PNG, or JPEG (quality 95)"},
      {"--hdr", "F.exr|F.pfm", "write linear radiance before exposure as float32 EXR or PFM"},
      {"--json", "F.json",
       "write the timings (every timed frame), light statistics and provenance as JSON (pbr bench's schema); pbr "
       "render's report also holds the settings that decided its frame (render_settings), which --settings reads"},
      {"--csv", "F.csv",
       "write the results as CSV, header row first, and their provenance and settings beside it in F.provenance.txt"},
      {"--trace", "F.json",
       "write the timed frames as a Chrome trace (Perfetto, chrome://tracing); merged shards each get a process on "
       "its own timeline (shards written by a pbr that records pass start times)"},
      {"--out-dir", "DIR", "folder for the images, the CSV, its provenance and the chart"},
      {"--no-chart", "", "skip the chart (drawn by scripts/plot_accuracy.py with python3-matplotlib)"},
      {"--settings", "F.json|F.json#K",
       "take every option that decides the frame from the render_settings of a report pbr render --json wrote, so "
       "that it renders the same frame, or from configuration K of a pbr bench report; options given here replace "
       "the report's",
       "", "none: the options given here and their defaults"},

      // The viewer.
      {"--paused", "", "start with the light animation, or the glTF animation the scene plays, paused (key P toggles)"},
      {"--quit-after", "K", "draw K frames, write --screenshot if given and quit (for unattended runs)", "",
       "run until the window is closed"},
      {"--screenshot", "F.png|F.jpg", "where F12 and the end of a --quit-after run save the frame"},
      {"--screenshot-ui", "", "screenshots show the window with its overlay, not the frame alone"},
      {"--no-ui", "", "hide the overlay (frame-time graph, light statistics, controls); the title then shows the "
                      "pass times"},
      {"--env-dir", "DIR", "folder of .hdr files the overlay offers", "",
       "the environment's folder, else the asset folder's environments/"},
  };
}

// A command's use of a row: the row's name and, where the command's default differs, its own. `swept`: the command
// takes a comma-separated list of the row's values and measures each in turn.
struct Use {
  Use(const char* name_) : name(name_) {}  // implicit: a bare name takes the row as it is
  Use(const char* name_, std::string defaultValue_) : name(name_), defaultValue(std::move(defaultValue_)) {}
  static Use swept(const char* name_, std::string defaultValue_) {
    Use use(name_, std::move(defaultValue_));
    use.sweep = true;
    return use;
  }
  static Use text(const char* name_, std::string defaultText_) {
    Use use(name_);
    use.defaultText = std::move(defaultText_);
    return use;
  }
  std::string name;
  std::optional<std::string> defaultValue;
  std::optional<std::string> defaultText;
  bool sweep = false;
};

std::vector<Use> commandUses(Command command) {
  const std::vector<Use> scene = {"--allow-outside-uris", "--strict", "--gltf-scene", "--animation", "--time"};
  std::vector<Use> uses;
  switch (command) {
    case Command::Render:
      uses = {"--scene", "--model", "--visibility", "--variant", "--hdr-format", "--gbuffer", "--lights",
              "--view-angle", "--spot-share", "--culling", "--shadows", "--shadow-filter", "--transparency",
              "--tonemap", "--shadow-atlas", "--shadow-draws", "--shadow-cache", "--tile", "--slices", "--assign-shape", "--aa",
              "--debug", "--stats", "--size", "--exposure", "--ev100", "--camera", "--environment",
              "--environment-intensity", "--out", "--hdr", "--warmup", "--frames", "--capture-frame", "--json",
              "--settings", "--timing", "--egl-platform"};
      break;
    case Command::Bench: {
      const BenchSettings sweep;
      uses = {Use("--scene", sweep.scene),
              Use::swept("--lights", listText(sweep.lights, [](int n) { return std::to_string(n); })),
              Use::swept("--culling", listText(sweep.culling, [](Culling c) { return toString(c); })),
              Use::swept("--model", listText(sweep.models, [](ShadingModel m) { return toString(m); })),
              Use("--size", sizeText(sweep.size)), Use("--warmup", std::to_string(sweep.warmup)),
              Use("--frames", std::to_string(sweep.frames)), "--max-seconds", "--constant-density", "--spot-share",
              "--shadows", "--tonemap", "--shadow-filter", "--shadow-atlas",
              Use("--shadow-cache", sweep.shadows.cache ? "on" : "off"), "--pair-cost", "--pair-materials",
              "--pair-lights", "--pair-scene",
              "--rounds", "--csv", "--json", "--trace", "--shard",
              "--timing", "--egl-platform"};
      break;
    }
    case Command::BenchMerge:
      return {"--csv", "--json", "--trace", "--allow-mixed"};
    case Command::Experiment:
      return {Use("--out-dir", "out/experiments"), Use("--size", sizeText({640, 360})), "--frames", "--scene",
              "--egl-platform"};
    case Command::View: {
      const ViewerOptions viewer;
      uses = {Use("--scene", viewer.sceneName), "--lights", "--view-angle", "--spot-share",
              Use("--model", toString(viewer.frame.model)), "--culling", "--shadows", "--shadow-filter",
              "--transparency", "--tonemap", "--shadow-atlas", "--shadow-cache", "--aa", "--exposure", "--ev100", "--camera",
              "--environment", "--environment-intensity", Use("--size", sizeText(viewer.size)), "--paused",
              "--quit-after", "--screenshot", "--screenshot-ui", "--no-ui", "--env-dir", "--timing"};
      break;
    }
    case Command::Reference: {
      const reference::ReferenceOptions defaults;
      uses = {Use("--scene", "sphere-grid"), "--lights", "--view-angle", "--spot-share",
              Use("--size", sizeText({640, 360})), "--hdr", "--out", "--tonemap", "--exposure", "--ev100",
              "--threads", "--geometry", "--shadows", Use::text("--variant", toString(defaults.forms))};
      break;
    }
    case Command::Accuracy:
      uses = {"--scenes", "--variants", Use("--size", sizeText({320, 180})), "--pair-size", "--pair-lights",
              Use("--rounds", "9"), "--no-cost", "--shadow-rows", "--shadow-scene", "--shadow-cost-size",
              "--transparency-rows", "--tonemap", "--transparency-scene", "--transparency-cost-size",
              Use("--out-dir", "out/accuracy"), "--brdf-slices", "--brdf-slice-size", "--no-chart", "--threads",
              "--timing", "--egl-platform"};
      break;
  }
  uses.insert(uses.end(), scene.begin(), scene.end());
  return uses;
}

std::vector<OptionSpec> makeCommandOptions(Command command) {
  std::vector<OptionSpec> specs;
  for (const Use& use : commandUses(command)) {
    const auto& table = optionTable();
    const auto row = std::find_if(table.begin(), table.end(), [&](const OptionSpec& s) { return s.name == use.name; });
    if (row == table.end()) throw std::logic_error(std::string("pbr ") + toString(command) + " takes " + use.name +
                                                   ", which the option table lacks");
    OptionSpec spec = *row;
    if (use.defaultValue) {
      spec.defaultValue = *use.defaultValue;
      spec.defaultText.clear();
    }
    if (use.defaultText) spec.defaultText = *use.defaultText;
    if (use.sweep) {
      spec.metavar = "LIST";
      spec.help += "; a comma-separated list, each measured in turn";
    }
    specs.push_back(std::move(spec));
  }
  return specs;
}

}  // namespace

const char* toString(Command command) {
  switch (command) {
    case Command::Render: return "render";
    case Command::Bench: return "bench";
    case Command::BenchMerge: return "bench-merge";
    case Command::Experiment: return "experiment";
    case Command::View: return "view";
    case Command::Reference: return "reference";
    case Command::Accuracy: return "accuracy";
  }
  return "?";
}

const std::vector<OptionSpec>& optionTable() {
  static const std::vector<OptionSpec> table = makeTable();
  return table;
}

const std::vector<OptionSpec>& commandOptions(Command command) {
  static std::map<Command, std::vector<OptionSpec>> tables;
  auto it = tables.find(command);
  if (it == tables.end()) it = tables.emplace(command, makeCommandOptions(command)).first;
  return it->second;
}

}  // namespace pbr
