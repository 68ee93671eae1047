#include <algorithm>
#include <cstdio>
#include <iostream>
#include <optional>

#include "app/args.hpp"
#include "app/bench/bench_report.hpp"
#include "app/bench/bench_run.hpp"
#include "app/commands.hpp"
#include "app/option_table.hpp"
#include "app/common_options.hpp"
#include "app/file_clash.hpp"
#include "app/frame_settings.hpp"
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
#include "renderer/frame_limits.hpp"
#include "renderer/renderer.hpp"

namespace pbr {

namespace {

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
    std::printf("shadows: %u lights shadowed, %u views rendered (%u of them kept from the frame before), %u skipped "
                "(no receiver in view), atlas %dx%d (%.0f MiB, %.1f %% used)\n",
                h.shadowedLights, h.viewsRendered, h.viewsKept, h.viewsSkipped, atlas, atlas,
                double(shadowAtlasBytes(atlas)) / (1 << 20), 100.0 * double(h.texelsUsed) / (double(atlas) * atlas));
    if (h.reused) {
      std::printf("shadows: the last frame kept the maps of the frame before (nothing they depend on changed; "
                  "--shadow-cache off draws them every frame)\n");
    } else {
      std::printf("shadows: CPU in the last frame: %.2f ms reading the occupied clusters back (waiting for the GPU), "
                  "%.2f ms planning, %.2f ms recording %u draws (%s; %u of them one-sided, closed casters "
                  "seen from outside)\n",
                  h.readBackMs, h.planMs, h.recordMs, h.draws, h.drawsPerLight ? "per-light" : "per-view",
                  h.oneSidedDraws);
    }
    if (h.planesLeftOut) {
      std::printf("shadows: %u planar casters left out of views (no visible surface beyond their plane from the "
                  "light)\n", h.planesLeftOut);
    }
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
    std::printf("lighting: %u of %u 8x8 tiles hold a surface and were shaded; the others took the background alone\n",
                s.pairs.surfaceTiles, s.pairs.tiles);
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

// What the command line asks of pbr render, read and checked before a scene is loaded or a context made.
struct RenderRequest {
  std::string sceneName;
  RenderSettings record;   // every option that decides the frame, as --json records it
  FrameSettings settings;  // what the record decides, over the commands' cluster grid (measuredGrid)
  SceneParams sceneParams;
  glm::ivec2 size{0};
  int warmup = 0, frames = 0, captureFrame = 0;
  bool stats = false;
  std::string outPng, outHdr, outJson, timing;
  EglPlatform platform = EglPlatform::Auto;
};

RenderRequest readRequest(const std::vector<OptionSpec>& specs, const Args& args) {
  RenderRequest r;
  r.sceneName = args.get("--scene");
  r.record = renderSettings(specs, args);
  r.settings = frameSettings(r.record, {measuredGrid(), {}});
  // Blinn-Phong frames are clamped in LDR: no tone curve or exposure reaches them.
  if (r.settings.frame.model != ShadingModel::Pbr && args.has("--tonemap")) {
    throw UsageError("--tonemap is the pbr model's display transform; --model blinn-phong frames are clamped");
  }
  if (r.settings.frame.model != ShadingModel::Pbr && args.get("--exposure") == "auto") {
    throw UsageError("--exposure auto meters the pbr model's frames; --model blinn-phong frames are clamped");
  }
  r.sceneParams = sceneFileParams(args);
  r.sceneParams.defaultEnvironment = defaultEnvironment(args);
  applySceneShapeOptions(args, r.sceneParams);
  r.stats = args.has("--stats");
  r.size = args.getSize("--size");
  r.warmup = args.getInt("--warmup", 0, 100000);
  r.frames = args.getInt("--frames", 1, 100000);
  r.captureFrame = checkedCaptureFrame(args, r.warmup, r.frames);
  r.outPng = args.get("--out");
  r.outHdr = args.get("--hdr");
  r.outJson = args.get("--json");
  // Every output's kind is known from its name before anything renders.
  if (!r.outPng.empty()) ldrFileFormat(r.outPng);
  if (!r.outHdr.empty()) hdrFileFormat(r.outHdr);
  if (!r.outJson.empty()) requireExtension(r.outJson, ".json");
  r.timing = args.get("--timing");
  r.platform = parseEglPlatform(args.get("--egl-platform"));
  chooseTimingMode(r.timing, "");  // reject a bad mode before making a context
  return r;
}

// A debug channel that shows what the scene lacks would be a blank legend: refused, naming what is missing.
void checkDebugChannel(const FrameOptions& frame, const Scene& scene) {
  if (!frame.debug) return;
  const DebugNeeds needs = debugChannelInfo(*frame.debug).needs;
  const ShadowMode shadowMode = frame.shadows.mode;
  if (needs == DebugNeeds::ShadowCaster && !anyShadowCaster(scene.lights, scene.directionalLights, shadowMode)) {
    throw UsageError("--debug " + std::string(toString(*frame.debug)) + ": no light of the scene casts shadows under " +
                     "--shadows " + toString(shadowMode) + " (--shadows on makes every light cast)");
  }
  if (needs == DebugNeeds::BlendSurface && !hasBlendMaterial(scene)) {
    throw UsageError("--debug " + std::string(toString(*frame.debug)) +
                     ": the scene has no material with alphaMode BLEND");
  }
}

void printScene(const Scene& scene, glm::ivec2 size, const FrameOptions& frame) {
  const std::string directional =
      scene.directionalLights.empty() ? "" : " + " + std::to_string(scene.directionalLights.size()) + " directional";
  // A channel other than the cluster views replaces the frame, and the renderer does not filter it.
  const std::optional<DebugChannel>& debug = frame.debug;
  const std::string shownAa = debug && !needsClusterGrid(*debug) ? "none (debug " + std::string(toString(*debug)) + ")"
                                                                  : std::string(toString(frame.aa));
  const std::string shownCurve =
      frame.model == ShadingModel::Pbr ? ", tonemap " + std::string(toString(frame.toneCurve)) : "";
  std::printf("scene: %s, %dx%d, %zu lights%s, model %s%s, culling %s, aa %s%s\n", scene.name.c_str(), size.x,
              size.y, scene.lights.size(), directional.c_str(), toString(frame.model),
              (" (" + describeTerms(frame.model, frame.variant) + ")").c_str(), toString(frame.culling),
              shownAa.c_str(), shownCurve.c_str());
}

// The first frame, the warm-up and the timed frames, printed as they end; the result of the timed ones.
BenchResult timedRun(Renderer& renderer, const FrameOptions& options, Profiler& profiler, const RenderRequest& r,
                     const Scene& scene) {
  renderer.renderFrame(options, profiler);
  printFirstFrame(profiler.takeResults(true).front());
  printWarmUp(renderer.warmUp(options, profiler, r.warmup));
  BenchResult result;
  result.config = {scene.name, r.size, static_cast<int>(scene.lights.size()), options.culling, options.model, 1.0f,
                   options.shadows};
  TimedFrames timed = timeFrames(renderer, options, profiler, r.frames);
  result.frames = std::move(timed.frames);
  result.processCpuShare = timed.processCpuShare;
  result.summarize();
  result.memory = {renderer.gbuffer().bytes(), renderer.clusters().bytes(), renderer.lights().bytes()};
  printTimings(result, profiler.mode());
  return result;
}

// The --json report: pbr bench's schema with this one configuration, and the record that reproduces the frame.
BenchReport renderReport(const RenderRequest& r, const Scene& scene, BenchResult result, Provenance provenance,
                         const std::optional<MeteredExposure>& metered, float shownExposure,
                         const std::string& gbufferLayout) {
  const FrameOptions& frame = r.settings.frame;
  BenchReport report;
  report.provenance = std::move(provenance);
  report.provenance.set("shading_variant", describeTerms(frame.model, frame.variant));
  report.provenance.set("tone_curve", frame.model == ShadingModel::Pbr ? toString(frame.toneCurve) : "none (clamped)");
  report.provenance.set("exposure", metered ? "auto" : fixedDecimals(shownExposure, 6));
  if (metered) report.provenance.set("ev100_metered", fixedDecimals(metered->ev100, 3));
  report.provenance.set("gbuffer_layout", gbufferLayout);
  report.settings.scene = scene.name;
  report.settings.size = r.size;
  report.settings.lights = {result.config.lights};
  report.settings.culling = {frame.culling};
  report.settings.models = {frame.model};
  report.settings.warmup = r.warmup;
  report.settings.frames = r.frames;
  report.settings.maxSeconds = 0.0;
  report.settings.timing = r.timing;
  report.settings.shadows = frame.shadows;
  report.results.push_back(std::move(result));
  report.renderSettings = r.record;
  return report;
}

// With --stats the G-buffer's layout and the transmission background's memory; the metered exposure where
// --exposure auto metered one.
void printFrameMemoryAndExposure(const RenderRequest& r, const Scene& scene, const std::string& gbufferLayout,
                                 const std::optional<MeteredExposure>& metered) {
  if (r.stats) std::printf("gbuffer: %s\n", gbufferLayout.c_str());
  if (r.stats && hasTransmissiveMaterial(scene)) {
    const uint64_t bytes = transmissionBackgroundBytesPerPixel(r.settings.renderer.hdrFormat) * uint64_t(r.size.x) *
                           uint64_t(r.size.y);
    std::printf("transmission: the opaque frame copied with its mip chain for the transmissive materials to see "
                "through, %.1f MiB\n", double(bytes) / double(1 << 20));
  }
  if (metered) {
    std::printf("exposure: auto, EV100 %.2f metered from the frame (exposure %.4g, as --ev100 %.2f --exposure 1 "
                "sets it)\n", double(metered->ev100), exposureFromEv100(metered->ev100), double(metered->ev100));
  }
}

// The scene the request names, with the command line's environment, camera and exposure applied, checked against
// the debug channel and the outputs.
struct PreparedScene {
  Scene scene;
  ExposureChoice exposure;
};

PreparedScene prepareScene(const RenderRequest& r, const Args& args) {
  PreparedScene p{resolveScene(r.sceneName, r.sceneParams), {}};
  applyEnvironmentOptions(args, p.scene);
  applyCameraOption(args, p.scene);
  p.exposure = applyExposureOptions(args, p.scene);
  checkDebugChannel(r.settings.frame, p.scene);
  checkOutputsApart(sceneInputs(r.sceneName, p.scene),
                    {{"--out", r.outPng}, {"--hdr", r.outHdr}, {"--json", r.outJson}});
  return p;
}

// The outputs asked for, opened before rendering so that an unwritable path fails at once; each is renamed into
// place only once all of it is written.
struct RenderOutputs {
  explicit RenderOutputs(const RenderRequest& r) {
    if (!r.outPng.empty()) png.emplace(r.outPng);
    if (!r.outHdr.empty()) hdr.emplace(r.outHdr);
    if (!r.outJson.empty()) json.emplace(r.outJson);
  }
  std::optional<OutputFile> png, hdr, json;
};

// The untimed frame after the timed ones: its images and what it measured.
struct FinalFrame {
  ImageRgba8 ldr;
  ImageRgbaF hdr;
  std::optional<MeteredExposure> metered;
  std::string gbufferLayout;
};

// Captures and GPU counters come from one more frame that nobody times.
FinalFrame renderFinalFrame(Renderer& renderer, FrameOptions options, TimingMode mode, const RenderRequest& r,
                            const Scene& scene, const RenderOutputs& outputs, BenchResult& result) {
  FinalFrame f;
  options.stats = r.stats || outputs.json;
  Profiler untimed(mode);
  renderer.renderFrame(options, untimed, {outputs.png ? &f.ldr : nullptr, outputs.hdr ? &f.hdr : nullptr});
  result.stats = renderer.lightStats();
  printLightStats(result.stats, renderer, options);
  f.gbufferLayout = renderer.gbuffer().layout.describe(renderer.gbuffer().precision);
  f.metered = renderer.meteredExposure();
  printFrameMemoryAndExposure(r, scene, f.gbufferLayout, f.metered);
  checkGlError("rendering");
  return f;
}

void writeOutputs(RenderOutputs& outputs, const RenderRequest& r, const PreparedScene& p, const FinalFrame& f,
                  BenchResult result, Provenance provenance) {
  if (outputs.png) {
    outputs.png->write([&](std::ostream& out) { writeLdr(out, ldrFileFormat(r.outPng), f.ldr); });
    std::printf("wrote %s\n", r.outPng.c_str());
  }
  const float shownExposure = f.metered ? float(exposureFromEv100(f.metered->ev100)) : p.exposure.exposure;
  const FrameExposure shown{r.settings.frame.model == ShadingModel::Pbr, shownExposure, f.metered.has_value()};
  for (const std::string& note : frameNotes(p.scene, r.size, shown, outputs.png ? &f.ldr : nullptr)) {
    std::printf("note: %s\n", note.c_str());
  }
  if (outputs.hdr) {
    outputs.hdr->write([&](std::ostream& out) { writeHdr(out, hdrFileFormat(r.outHdr), f.hdr); });
    std::printf("wrote %s\n", r.outHdr.c_str());
  }
  if (outputs.json) {
    const BenchReport report = renderReport(r, p.scene, std::move(result), std::move(provenance), f.metered,
                                            shownExposure, f.gbufferLayout);
    outputs.json->write([&](std::ostream& out) { writeBenchJson(out, report); });
    std::printf("wrote %s\n", r.outJson.c_str());
  }
}

}  // namespace

int runRender(const std::vector<std::string>& commandLine) {
  const auto& specs = commandOptions(Command::Render);
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
  const RenderRequest r = readRequest(specs, args);
  const PreparedScene prepared = prepareScene(r, args);
  const Scene& scene = prepared.scene;
  RenderOutputs outputs(r);

  auto context = createHeadlessContext(r.platform);
  const ContextInfo& info = context->info();
  std::printf("renderer: %s | %s | %s\n", info.renderer.c_str(), info.version.c_str(), info.platform.c_str());
  for (const std::string& note : scene.notes) std::printf("note: %s\n", note.c_str());
  if (!prepared.exposure.note.empty()) std::printf("note: %s\n", prepared.exposure.note.c_str());
  printScene(scene, r.size, r.settings.frame);

  const ShaderLibrary shaders;
  Profiler profiler(chooseTimingMode(r.timing, info.renderer));
  Profiler precomputeProfiler(profiler.mode());
  RendererConfig rendererConfig = r.settings.renderer;
  rendererConfig.precomputeProfiler = &precomputeProfiler;
  const FrameCapturer capturer;  // before the renderer, which holds on to it
  Renderer renderer(shaders, scene, r.size.x, r.size.y, rendererConfig);
  if (renderer.ibl()) {
    std::printf("environment: %s, IBL precomputation (%s):\n",
                scene.environment->file.empty() ? "procedural sky" : scene.environment->file.c_str(),
                describe(precomputeProfiler.mode()));
    printPrecomputeTimings(precomputeProfiler.takeResults(true));
  }
  if (r.captureFrame) {
    renderer.captureFrame(r.captureFrame, capturer);
    std::printf("%s\n", capturer.describe(r.captureFrame).c_str());
  }
  FrameOptions options = r.settings.frame;
  options.exposure = prepared.exposure.exposure;
  options.autoExposure = prepared.exposure.autoExposure;
  BenchResult result = timedRun(renderer, options, profiler, r, scene);
  const FinalFrame last = renderFinalFrame(renderer, options, profiler.mode(), r, scene, outputs, result);
  writeOutputs(outputs, r, prepared, last, std::move(result), collectProvenance(info, profiler.mode()));
  return 0;
}

}  // namespace pbr
