#include <algorithm>
#include <cstdio>
#include <iostream>
#include <optional>

#include "app/args.hpp"
#include "app/bench/bench_report.hpp"
#include "app/bench/bench_run.hpp"
#include "app/commands.hpp"
#include "app/common_options.hpp"
#include "app/file_clash.hpp"
#include "app/frame_notes.hpp"
#include "app/render_settings.hpp"
#include "app/scene_source.hpp"
#include "core/gl/context.hpp"
#include "core/gl/frame_capture.hpp"
#include "core/scene/exposure.hpp"
#include "core/io/image_output.hpp"
#include "core/scene/messages.hpp"
#include "core/io/output_file.hpp"
#include "lighting/lighting_pass.hpp"
#include "renderer/renderer.hpp"

namespace pbr {

namespace {

const std::vector<OptionSpec>& renderOptions() {
  static const FrameOptions frame;
  static const RendererConfig renderer;
  static const std::vector<OptionSpec> specs = {
      {"--scene", "NAME|FILE", "built-in scene (" + builtinSceneList() + ") or scene file (.json, .gltf, .glb)",
       "default", ""},
      {"--model", "MODEL", "shading model: pbr or blinn-phong", toString(frame.model), ""},
      {"--visibility", "V", "PBR Smith visibility: exact (height-correlated), hammon or separable", "",
       std::string(toString(frame.variant.visibility)) + ", or --variant's"},
      {"--variant", "K=V,...|study", "shading variant, PBR: visibility=exact|hammon|separable, ndf=ggx|beckmann, "
                                     "fresnel=schlick|exact|schlick-sg, diffuse=lambert-1-f|lambert|burley|"
                                     "lambert-1-f-vh; or, alone, study: the PBR model "
                                     "of the Blinn-Phong-vs-PBR study, GGX, Hammon's visibility, Schlick Fresnel "
                                     "and Lambert weighted by (1 - F(v.h)); Blinn-Phong: lobe=pow or sg, "
                                     "the lobe's spherical-Gaussian fit (one exp2 instead of pow)", "",
       toString(frame.variant) + "," + toString(frame.variant.lobe)},
      {"--hdr-format", "F", "HDR radiance target: rgba16f, r11g11b10f or rgba32f", toString(renderer.hdrFormat), ""},
      {"--gbuffer", "P", "G-buffer precision: lean (16 bytes per pixel) or float (unquantised, 44 bytes)",
       toString(renderer.gbuffer), ""},
      lightsOption("the scene's; 256 for default"),
      viewAngleOption(),
      spotShareOption(),
      {"--culling", "C",
       "clustered, none (brute force: every light for every pixel) or auto (per frame, whichever the times "
       "measured here predict cheaper)", toString(kCommandCulling), ""},
      shadowModeOption(),
      shadowFilterOption(),
      transparencyOption(),
      toneMapOption(),
      shadowAtlasOption(),
      {"--shadow-draws", "auto|per-view|per-light",
       "how the shadow casters are drawn, the same depths either way: a draw per caster and view, or per caster and "
       "run of a light's views with each view's viewport chosen in the vertex shader (fewer draws to record; needs "
       "GL_ARB_shader_viewport_layer_array), or per-light on a GPU that has it and per-view on a CPU rasterizer",
       toString(ShadowSettings{}.draws), ""},
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
      {"--aa", "none|fxaa",
       "anti-aliasing of the display image (the PNG), after tone mapping: FXAA 3.11 or none; --hdr captures are "
       "never filtered", toString(kDisplayAntiAliasing), ""},
      {"--debug", "CHANNEL",
       "a debug channel with its legend in place of the frame: " + debugChannelNames() +
           " (efficiency: contributing / evaluated light-pixel pairs per pixel; shadows: the light casting lights "
           "bring over what they would unshadowed, 0 black, with the shadow atlas inset; clusters and slices need "
           "--culling clustered)",
       "", "none, the frame itself"},
      {"--stats", "",
       "count light statistics on the GPU (visible lights, culling efficiency) in an untimed extra frame"},
      {"--size", "WxH", "frame size in pixels", sizeText({1280, 720}), ""},
      {"--exposure", "X|auto",
       "exposure multiplier before the tone curve, or auto: metered from the frame itself on the GPU (the mean log2 "
       "luminance between its 10th and 90th percentiles shown as 0.18), reported as EV100; a scene camera's "
       "exposure keeps priority", "", "the scene's, 1"},
      ev100Option(),
      cameraOption(),
      environmentOption(),
      environmentIntensityOption(),
      {"--out", "F.png|F.jpg", "write the final 8-bit sRGB frame as PNG, or JPEG (quality 95)"},
      {"--hdr", "F.exr|F.pfm", "write linear radiance before exposure as float32 EXR or PFM"},
      {"--warmup", "K", "untimed frames after the first, more while a cluster's light list does not fit yet", "2", ""},
      {"--frames", "K", "timed frames: median and spread of each pass over them", "5", ""},
      {"--capture-frame", "K",
       "mark the K-th frame rendered for graphics debuggers, counting from 1 over every frame of the run (the first, "
       "the warm-up, the timed ones and the final capture frame, 1 to --warmup + --frames + 2): captured through "
       "RenderDoc's in-application API when run under RenderDoc (renderdoccmd capture ...), and always wrapped in a "
       "debug group and marker 'capture frame K'", "", "none"},
      {"--json", "F.json", "write the timings (every timed frame), light statistics, provenance and the settings that "
                           "decided the frame (render_settings) as JSON (pbr bench schema)"},
      {"--settings", "F.json|F.json#K",
       "take every option that decides the frame from the render_settings of a report pbr render --json wrote, so "
       "that it renders the same frame, or from configuration K of a pbr bench report; options given here replace "
       "the report's",
       "", "none: the options given here and their defaults"},
      timingOption(),
      eglPlatformOption(),
      allowOutsideUrisOption(),
      strictOption(),
      gltfSceneOption(),
      animationOption(),
      timeOption(),
  };
  return specs;
}

void printPasses(const std::vector<PassTiming>& passes, double frameMs) {
  for (const PassTiming& p : passes) std::printf("  %-10s %9.3f ms\n", p.name.c_str(), p.ms);
  std::printf("  %-10s %9.3f ms\n", "frame", frameMs);
}

// The first frame pays for shader compilation and first-touch allocations: it is reported alone, never in the
// medians.
void printFirstFrame(const FrameTiming& first) {
  std::printf("first frame (shader compilation, allocation; not in the medians): %.3f ms:", first.gpuMs);
  for (const PassTiming& p : first.passes) std::printf(" %s %.3f", p.name.c_str(), p.ms);
  std::printf("\n");
}

void printWarmUp(const WarmUpReport& w) {
  std::printf("warm-up: %d untimed frame%s after the first", w.frames, w.frames == 1 ? "" : "s");
  if (w.listSizingFrames) {
    std::printf(" (%d of them to size the light-index list to the measured demand)", w.listSizingFrames);
  }
  if (w.cullingFrames) {
    std::printf(" (%d of them timing culling auto's paths or the grid's tile sides)", w.cullingFrames);
  }
  std::printf("\n");
  if (w.overflowedClusters) {
    std::printf("warm-up: the light-index list or the light masks reached their limit: %u clusters are shaded by "
                "brute force in every timed frame\n", w.overflowedClusters);
  }
}

void printTimings(const BenchResult& r, TimingMode mode) {
  std::printf("timing: %s, median of %zu warm frames (p10-p90 of the frame %.3f-%.3f ms)\n", describe(mode),
              r.frames.size(), r.frameTime.p10, r.frameTime.p90);
  std::vector<PassTiming> passes;
  for (const PassSummary& p : r.passes) passes.push_back({p.name, p.ms.median, 0.0});
  printPasses(passes, r.frameTime.median);
  std::printf("  %-10s %9.3f ms (CPU clock)\n", "wall", r.cpuTime.median);
}

void printLightStats(const LightStats& s, const Renderer& renderer, const FrameOptions& options) {
  std::printf("lights: %u in the frame", s.lights);
  if (s.culling == Culling::Clustered) {
    const glm::uvec3 d = renderer.clusters().dims();
    if (options.stats) std::printf(", %u survive frustum culling", s.visibleLights);
    std::printf("\nclusters: %ux%ux%u, %u holding a surface (%.1f %%), %u non-empty, %.1f lights per non-empty "
                "cluster (max %u), %llu index entries\n",
                d.x, d.y, d.z, s.activeClusters, s.clusters ? 100.0 * s.activeClusters / s.clusters : 0.0,
                s.nonEmptyClusters, s.averagePerNonEmpty(), s.maxPerCluster,
                static_cast<unsigned long long>(s.indexEntries));
    std::printf("assignment: %s\n", renderer.clusters().shapeSummary().c_str());
    if (!renderer.tileSummary().empty()) std::printf("grid: %s\n", renderer.tileSummary().c_str());
    if (s.overflowedClusters) {
      std::printf("clusters: %u clusters did not fit the light index list or the light masks and were shaded by "
                  "brute force\n", s.overflowedClusters);
    }
  } else {
    std::printf("\n");
  }
  if (s.decision) std::printf("culling: auto ran %s\n", s.decision->describe().c_str());
  if (s.shadows.shadowedLights || s.shadows.unshadowedLights) {
    const ShadowStats& h = s.shadows;
    const int atlas = options.shadows.atlasSize;
    std::printf("shadows: %u lights shadowed, %u views rendered, %u skipped (no receiver in view), atlas %dx%d "
                "(%.0f MiB, %.1f %% used)\n",
                h.shadowedLights, h.viewsRendered, h.viewsSkipped, atlas, atlas,
                double(shadowAtlasBytes(atlas)) / (1 << 20), 100.0 * double(h.texelsUsed) / (double(atlas) * atlas));
    std::printf("shadows: CPU in the last frame: %.2f ms reading the occupied clusters back (waiting for the GPU), "
                "%.2f ms planning, %.2f ms recording %u draws (%s)\n",
                h.readBackMs, h.planMs, h.recordMs, h.draws, h.drawsPerLight ? "per-light" : "per-view");
    if (h.cascadeTexelMax > 0.0f) {
      std::printf("shadows: directional cascades' texels %.3g-%.3g scene units (metres) across\n",
                  double(h.cascadeTexelMin), double(h.cascadeTexelMax));
    }
    if (h.shrunkLights) {
      std::printf("shadows: the atlas is full: %u lights got smaller maps than their size on screen asks "
                  "(--shadow-atlas)\n", h.shrunkLights);
    }
    if (h.unshadowedLights) {
      std::printf("shadows: the atlas is full: %u casting lights got no map and are shaded unshadowed "
                  "(--shadow-atlas)\n", h.unshadowedLights);
    }
  }
  if (s.droppedLayers) {
    warnOnce("transparency: " + std::to_string(s.droppedLayers) + " BLEND fragments of the last frame were left out "
             "of --transparency exact (room for " + std::to_string(kLayerNodesPerPixel) + " a pixel on average, the " +
             std::to_string(kMaxLayersPerPixel) + " nearest of a pixel composited)");
  }
  if (options.stats) {
    std::printf("culling efficiency: %.3f (%llu of %llu light-pixel pairs evaluated contribute)\n",
                s.cullingEfficiency(), static_cast<unsigned long long>(s.pairs.contributing),
                static_cast<unsigned long long>(s.pairs.evaluated));
  }
}

// 0 without --capture-frame. The run renders at least the first frame, the warm-up, the timed frames and one
// untimed frame for captures and statistics (warm-up may add frames to size light lists, never fewer), so any K
// up to their sum exists: a K beyond it is refused before anything is rendered.
int checkedCaptureFrame(const Args& args, int warmup, int frames) {
  if (!args.has("--capture-frame")) return 0;
  const int last = warmup + frames + 2;
  const int frame = args.getInt("--capture-frame", 1, 1 << 30);
  if (frame > last) {
    throw UsageError("--capture-frame " + std::to_string(frame) + " is past the run's last frame, " +
                     std::to_string(last) + " (the first frame, --warmup " + std::to_string(warmup) + ", --frames " +
                     std::to_string(frames) + " and the capture frame)");
  }
  return frame;
}

void printPrecomputeTimings(const std::vector<FrameTiming>& frames) {
  for (const FrameTiming& f : frames) {
    for (const PassTiming& p : f.passes) std::printf("  %-16s %9.3f ms\n", p.name.c_str(), p.ms);
    std::printf("  %-16s %9.3f ms\n", "ibl total", f.gpuMs);
  }
}

}  // namespace

int runRender(const std::vector<std::string>& commandLine) {
  const auto& specs = renderOptions();
  // --settings F.json: the report's options, under the ones given here.
  const std::vector<std::string> argv = withSettingsFile(specs, commandLine);
  Args args(specs, argv);
  if (args.helpRequested()) {
    std::cout << Args::helpText("pbr render [options]",
                                "Renders a scene headlessly (EGL) through G-buffer, deferred lighting and post, "
                                "prints per-pass timings and writes captures.",
                                specs);
    return 0;
  }
  const std::string sceneName = args.get("--scene");
  const ShadingModel model = parseShadingModel(args.get("--model"));
  std::vector<std::string> variantKeys;
  ShadingVariant variant = parseShadingVariant(args.get("--variant"), &variantKeys);
  // A term of the other model, or one chosen twice, would be dropped without a word.
  for (const std::string& key : variantKeys) {
    if ((key == "lobe") != (model == ShadingModel::BlinnPhong)) {
      throw UsageError("--variant " + args.get("--variant") + ": " + key + " is a term of the " +
                       (key == "lobe" ? "blinn-phong" : "pbr") + " model, not of --model " + toString(model));
    }
  }
  if (args.has("--visibility")) {
    if (std::find(variantKeys.begin(), variantKeys.end(), "visibility") != variantKeys.end()) {
      throw UsageError("--visibility and --variant " + args.get("--variant") + " both choose the visibility term");
    }
    if (model != ShadingModel::Pbr) throw UsageError("--visibility is a term of the pbr model, not of --model " +
                                                     std::string(toString(model)));
    variant.visibility = parseVisibility(args.get("--visibility"));
  }
  RendererConfig rendererConfig = measuredGrid();
  rendererConfig.hdrFormat = parseHdrFormat(args.get("--hdr-format"));
  rendererConfig.gbuffer = parseGBufferPrecision(args.get("--gbuffer"));
  SceneParams sceneParams = sceneFileParams(args);
  sceneParams.defaultEnvironment = defaultEnvironment(args);
  applySceneShapeOptions(args, sceneParams);
  const Culling culling = parseCulling(args.get("--culling"));
  ClusterConfig& clusterConfig = rendererConfig.clusters;
  if (args.get("--tile") != "auto") {
    clusterConfig.tileTrial = false;
    clusterConfig.tileSize = args.getInt("--tile", 8, 512);
  }
  clusterConfig.slices = args.getInt("--slices", 1, 256);
  clusterConfig.lightPass = clusterConfig.fill = parseAssignShape(args.get("--assign-shape"));
  if (clusterConfig.fill == AssignShape::Cluster) clusterConfig.fill = AssignShape::Workgroup;
  const bool stats = args.has("--stats");
  const AntiAliasing aa = parseAntiAliasing(args.get("--aa"));
  ShadowSettings shadows = readShadowSettings(args);
  shadows.draws = parseShadowDraws(args.get("--shadow-draws"));
  std::optional<DebugChannel> debug;
  if (args.has("--debug")) debug = parseDebugChannel(args.get("--debug"));
  // The cluster views show the grid that only clustered culling builds; efficiency is measured either way.
  if (debug && needsClusterGrid(*debug) && culling == Culling::None) {
    throw UsageError(std::string("--debug ") + toString(*debug) + " needs --culling clustered");
  }
  // Blinn-Phong frames are clamped in LDR: no tone curve or exposure reaches them.
  const ToneCurve curve = readToneCurve(args);
  if (model != ShadingModel::Pbr && args.has("--tonemap")) {
    throw UsageError("--tonemap is the pbr model's display transform; --model blinn-phong frames are clamped");
  }
  if (model != ShadingModel::Pbr && args.get("--exposure") == "auto") {
    throw UsageError("--exposure auto meters the pbr model's frames; --model blinn-phong frames are clamped");
  }
  const glm::ivec2 size = args.getSize("--size");
  const int warmup = args.getInt("--warmup", 0, 100000);
  const int frames = args.getInt("--frames", 1, 100000);
  const int captureFrame = checkedCaptureFrame(args, warmup, frames);
  const std::string outPng = args.get("--out");
  const std::string outHdr = args.get("--hdr");
  const std::string outJson = args.get("--json");
  // Every output's kind is known from its name before anything renders.
  if (!outPng.empty()) ldrFileFormat(outPng);
  if (!outHdr.empty()) hdrFileFormat(outHdr);
  if (!outJson.empty()) requireExtension(outJson, ".json");
  const std::string timing = args.get("--timing");
  const EglPlatform platform = parseEglPlatform(args.get("--egl-platform"));
  chooseTimingMode(timing, "");  // reject a bad mode before making a context

  Scene scene = resolveScene(sceneName, sceneParams);
  applyEnvironmentOptions(args, scene);
  applyCameraOption(args, scene);
  const ExposureChoice exposure = applyExposureOptions(args, scene);
  const DebugNeeds needs = debug ? debugChannelInfo(*debug).needs : DebugNeeds::Nothing;
  if (needs == DebugNeeds::ShadowCaster && !anyShadowCaster(scene.lights, scene.directionalLights, shadows.mode)) {
    throw UsageError("--debug " + std::string(toString(*debug)) + ": no light of the scene casts shadows under " +
                     "--shadows " + toString(shadows.mode) + " (--shadows on makes every light cast)");
  }
  if (needs == DebugNeeds::BlendSurface && !hasBlendMaterial(scene)) {
    throw UsageError("--debug " + std::string(toString(*debug)) + ": the scene has no material with alphaMode BLEND");
  }
  checkOutputsApart(sceneInputs(sceneName, scene), {{"--out", outPng}, {"--hdr", outHdr}, {"--json", outJson}});
  // Opened before rendering, so that an unwritable path fails at once; each is renamed into place only once all of
  // it is written.
  std::optional<OutputFile> pngFile, hdrFile, jsonFile;
  if (!outPng.empty()) pngFile.emplace(outPng);
  if (!outHdr.empty()) hdrFile.emplace(outHdr);
  if (!outJson.empty()) jsonFile.emplace(outJson);

  auto context = createHeadlessContext(platform);
  const ContextInfo& info = context->info();
  std::printf("renderer: %s | %s | %s\n", info.renderer.c_str(), info.version.c_str(), info.platform.c_str());
  const std::string directional =
      scene.directionalLights.empty() ? "" : " + " + std::to_string(scene.directionalLights.size()) + " directional";
  for (const std::string& note : scene.notes) std::printf("note: %s\n", note.c_str());
  if (!exposure.note.empty()) std::printf("note: %s\n", exposure.note.c_str());
  // A channel other than the cluster views replaces the frame, and the renderer does not filter it.
  const std::string shownAa = debug && !needsClusterGrid(*debug) ? "none (debug " + std::string(toString(*debug)) + ")"
                                                                  : std::string(toString(aa));
  const std::string shownCurve = model == ShadingModel::Pbr ? ", tonemap " + std::string(toString(curve)) : "";
  std::printf("scene: %s, %dx%d, %zu lights%s, model %s%s, culling %s, aa %s%s\n", scene.name.c_str(), size.x,
              size.y, scene.lights.size(), directional.c_str(), toString(model),
              (" (" + describeTerms(model, variant) + ")").c_str(), toString(culling), shownAa.c_str(),
              shownCurve.c_str());

  const ShaderLibrary shaders;
  Profiler profiler(chooseTimingMode(timing, info.renderer));
  Profiler precomputeProfiler(profiler.mode());
  rendererConfig.precomputeProfiler = &precomputeProfiler;
  const FrameCapturer capturer;  // before the renderer, which holds on to it
  Renderer renderer(shaders, scene, size.x, size.y, rendererConfig);
  if (renderer.ibl()) {
    std::printf("environment: %s, IBL precomputation (%s):\n",
                scene.environment->file.empty() ? "procedural sky" : scene.environment->file.c_str(),
                describe(precomputeProfiler.mode()));
    printPrecomputeTimings(precomputeProfiler.takeResults(true));
  }
  if (captureFrame) {
    renderer.captureFrame(captureFrame, capturer);
    std::printf("%s\n", capturer.describe(captureFrame).c_str());
  }
  FrameOptions options{model, variant, culling, exposure.exposure, false, debug, aa, shadows, readTransparency(args),
                       curve};
  options.autoExposure = exposure.autoExposure;
  renderer.renderFrame(options, profiler);
  printFirstFrame(profiler.takeResults(true).front());
  printWarmUp(renderer.warmUp(options, profiler, warmup));

  BenchResult result;
  result.config = {scene.name, size, static_cast<int>(scene.lights.size()), culling, model, 1.0f, shadows};
  TimedFrames timed = timeFrames(renderer, options, profiler, frames);
  result.frames = std::move(timed.frames);
  result.processCpuShare = timed.processCpuShare;
  result.summarize();
  result.memory = {renderer.gbuffer().bytes(), renderer.clusters().bytes(), renderer.lights().bytes()};
  printTimings(result, profiler.mode());

  // Captures and GPU counters come from one more frame that nobody times.
  ImageRgba8 ldr;
  ImageRgbaF hdr;
  options.stats = stats || !outJson.empty();
  Profiler untimed(profiler.mode());
  renderer.renderFrame(options, untimed, {outPng.empty() ? nullptr : &ldr, outHdr.empty() ? nullptr : &hdr});
  result.stats = renderer.lightStats();
  printLightStats(result.stats, renderer, options);
  const std::optional<MeteredExposure> metered = renderer.meteredExposure();
  if (metered) {
    std::printf("exposure: auto, EV100 %.2f metered from the frame (exposure %.4g, as --ev100 %.2f --exposure 1 "
                "sets it)\n", double(metered->ev100), exposureFromEv100(metered->ev100), double(metered->ev100));
  }
  checkGlError("rendering");

  if (pngFile) {
    pngFile->write([&](std::ostream& out) { writeLdr(out, ldrFileFormat(outPng), ldr); });
    std::printf("wrote %s\n", outPng.c_str());
  }
  const float shownExposure = metered ? float(exposureFromEv100(metered->ev100)) : exposure.exposure;
  const FrameExposure shown{model == ShadingModel::Pbr, shownExposure, metered.has_value()};
  for (const std::string& note : frameNotes(scene, size, shown, outPng.empty() ? nullptr : &ldr)) {
    std::printf("note: %s\n", note.c_str());
  }
  if (hdrFile) {
    hdrFile->write([&](std::ostream& out) { writeHdr(out, hdrFileFormat(outHdr), hdr); });
    std::printf("wrote %s\n", outHdr.c_str());
  }
  if (jsonFile) {
    BenchReport report;
    report.provenance = collectProvenance(info, profiler.mode());
    report.provenance.set("shading_variant", describeTerms(model, variant));
    report.provenance.set("tone_curve", model == ShadingModel::Pbr ? toString(curve) : "none (clamped)");
    report.provenance.set("exposure", metered ? "auto" : fixedDecimals(shownExposure, 6));
    if (metered) report.provenance.set("ev100_metered", fixedDecimals(metered->ev100, 3));
    report.settings.scene = scene.name;
    report.settings.size = size;
    report.settings.lights = {result.config.lights};
    report.settings.culling = {culling};
    report.settings.models = {model};
    report.settings.warmup = warmup;
    report.settings.frames = frames;
    report.settings.maxSeconds = 0.0;
    report.settings.timing = timing;
    report.settings.shadows = shadows;
    report.results.push_back(std::move(result));
    report.renderSettings = renderSettings(specs, args);
    jsonFile->write([&](std::ostream& out) { writeBenchJson(out, report); });
    std::printf("wrote %s\n", outJson.c_str());
  }
  return 0;
}

}  // namespace pbr
