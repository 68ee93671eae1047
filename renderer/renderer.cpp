#include "renderer/renderer.hpp"

#include <algorithm>
#include <chrono>
#include <optional>
#include <stdexcept>

#include "core/gl/context.hpp"
#include "core/gl/gpu_mesh.hpp"
#include "core/gl/gpu_texture.hpp"
#include "core/gl/readback.hpp"
#include "core/scene/exposure.hpp"

namespace pbr {

namespace {

SurfaceTextures surfaceTextures(const GBuffer& g) {
  return {g.baseColor, g.normal, g.material, g.depth, g.specular ? &*g.specular : nullptr,
          g.clearcoat ? &*g.clearcoat : nullptr, g.sheen ? &*g.sheen : nullptr};
}

// Runs the passes in order, each timed as a pass of the profiler's current frame.
void runPassList(const PassList& passes, Profiler& profiler) {
  for (const FramePass& pass : passes) {
    ScopedPass scope(profiler, pass.name.c_str());
    pass.run();
  }
}

}  // namespace

Renderer::Renderer(const ShaderLibrary& shaders, const Scene& scene, int width, int height,
                   const RendererConfig& config)
    : sceneData_(scene),
      config_(config),
      scene_(shaders, scene, config.precomputeProfiler),
      targets_(std::make_unique<FrameTargets>(scene_.programs, width, height, config, scene_.geometry.layout(),
                                          scene_.geometry.hasTransmissive())),
      camera_(scene.camera),
      frameData_(makeFrameBlock(camera_, width, height)),
      frame_("frame.block", frameData_),
      lights_(&scene.lights) {}

void Renderer::setLights(const std::vector<PointLight>& lights) {
  scene_.lights.uploadPoints(lights);
  lightsSet_ = lights;
  lights_ = &lightsSet_;
  shadowedCache_.reset();
  ++lightsVersion_;
}

void Renderer::scenePosed(const std::vector<int>& changedMeshes) {
  scene_.geometry.updatePose(sceneData_, changedMeshes);
  ++poseVersion_;
  scene_.lights.uploadDirectional(sceneData_.directionalLights);
  setLights(sceneData_.lights);
}

bool Renderer::shadowed(ShadowMode mode) {
  if (!shadowedCache_ || shadowedCache_->first != mode) {
    shadowedCache_ = {mode, anyShadowCaster(*lights_, sceneData_.directionalLights, mode)};
  }
  return shadowedCache_->second;
}

ShadowFrameKey Renderer::shadowFrameKey(const ShadowSettings& settings, bool clustered) {
  return {frameData_, lightsVersion_, poseVersion_, settings.mode, settings.atlasSize,
          shadowDrawsPerLight(settings.draws), clustered, targets_->clusters.askedTileSize(), config_.clusters.slices};
}

void Renderer::renderShadows(const ShadowSettings& settings, bool clustered) {
  FrameTargets& t = *targets_;
  const ShadowFrameKey key = shadowFrameKey(settings, clustered);
  shadowDrawsPerLight_ = key.drawsPerLight;
  if (settings.cache && scene_.shadows.reuse(key)) {
    shadowReadBackMs_ = 0.0;
    return;
  }
  // Where the visible surfaces are: the cluster pass measured it, or, shading without it, the occupancy pass alone.
  if (!clustered) {
    const BlendedSurfaces blended = blendedSurfaces(t.blendTarget.id());
    t.clusters.setCasterPlanes(scene_.geometry.casterPlanes(sceneData_), frameData_.inverseView);
    t.clusters.measureOccupancy(frameData_, frame_, t.gbuffer.depth,
                                scene_.geometry.hasBlended() ? &blended : nullptr);
  }
  const auto start = std::chrono::steady_clock::now();
  const ShadowReceivers receivers(t.clusters.occupiedBoxes(), frameData_.inverseView);
  const uint32_t planeSides = t.clusters.planeSides();
  shadowReadBackMs_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  const ShadowInputs inputs{camera_,
                            float(width()) / float(height()),
                            height(),
                            *lights_,
                            scene_.lights.order(),
                            sceneData_.directionalLights,
                            scene_.geometry.bounds(),
                            receivers,
                            settings.mode,
                            settings.atlasSize,
                            scene_.geometry.casterPlanes(sceneData_),
                            planeSides};
  scene_.shadows.render(
      inputs,
      [this, perLight = key.drawsPerLight](GLuint framebuffer, const std::vector<ShadowCasterView>& views) {
        return scene_.geometry.renderDepth(sceneData_, framebuffer, views, perLight);
      },
      key, settings.cache);
}

bool Renderer::shadowDrawsPerLight(ShadowDraws draws) {
  if (!viewportFromVertex_) {
    viewportFromVertex_ = glHasExtension("GL_ARB_shader_viewport_layer_array");
    const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    softwareRenderer_ = isSoftwareRenderer(renderer ? renderer : "");
  }
  if (draws == ShadowDraws::PerLight && !*viewportFromVertex_) {
    throw std::runtime_error("--shadow-draws per-light: the driver lacks GL_ARB_shader_viewport_layer_array");
  }
  if (draws != ShadowDraws::Auto) return draws == ShadowDraws::PerLight;
  // A CPU rasterizer draws per view: llvmpipe took 450-485 ms instead of 265-298 for the default scene's 1,275
  // views with the viewports chosen per vertex (docs/shadows.md), where a GPU records fewer draws that way.
  return *viewportFromVertex_ && !softwareRenderer_;
}

BlendedSurfaces Renderer::blendedSurfaces(GLuint framebuffer) {
  return {[this, framebuffer](const BlendedProgram& program, BlendOrder order, int repeats, BlendedSet set) {
    frame_.bind(kFrameUbo.index);
    glViewport(0, 0, width(), height());
    scene_.geometry.drawBlended(framebuffer, camera_, program, order, repeats, set);
  }};
}

void Renderer::resize(int width, int height) {
  targets_.reset();  // free the old targets before allocating the new ones
  targets_ = std::make_unique<FrameTargets>(scene_.programs, width, height, config_, scene_.geometry.layout(),
                                            scene_.geometry.hasTransmissive());
  ++targetBuilds_;
  setCamera(camera_);
}

void Renderer::setCamera(const Camera& camera) {
  camera_ = camera;
  frameData_ = makeFrameBlock(camera, width(), height());
  frame_.update(frameData_);
}

PassList Renderer::passList(const FrameOptions& options, const FrameCapture& capture) {
  using R = FrameResource;
  FrameTargets& t = *targets_;
  // Auto lists the cluster pass its frames may run (renderFrame resolves it).
  const bool clustered = options.culling != Culling::None;
  const bool ibl = scene_.ibl && options.model == ShadingModel::Pbr;
  const bool shadows = shadowed(options.shadows.mode);
  const bool blended = scene_.geometry.hasBlended();
  // A debug channel (debug/debug_channel.hpp) shows only where the frame has what it draws: the cluster grid that
  // only clustered culling builds, a light that casts, a BLEND surface; without it the frame is shown as it is.
  const DebugChannelInfo* debug = options.debug ? &debugChannelInfo(*options.debug) : nullptr;
  if (debug && ((debug->needs == DebugNeeds::ClusterGrid && !clustered) ||
                (debug->needs == DebugNeeds::ShadowCaster && !shadows) ||
                (debug->needs == DebugNeeds::BlendSurface && !blended))) {
    debug = nullptr;
  }
  const DebugSource source = debug ? debug->source : DebugSource::Surface;
  const bool emission = debug && source == DebugSource::Emission;
  const bool efficiency = debug && source == DebugSource::PairCounts;
  const bool shadowView = debug && source == DebugSource::ShadowLight;
  // The surface channels draw the G-buffer alone, the transparency channel the BLEND layers it counts itself, the
  // emission channel post's picture of the radiance as the geometry pass leaves it: none needs the lit radiance.
  const bool unlit = debug && (source == DebugSource::Surface || source == DebugSource::Emission ||
                               source == DebugSource::Layers);
  const bool replacesDisplay = debug && debug->replacesDisplay;
  PassList passes;
  passes.push_back({"gbuffer", {R::Geometry, R::Camera}, {R::GBuffer, R::Radiance},
                    [this, &t] { scene_.geometry.render(t.gbuffer, frame_); }});
  if (clustered) {
    std::vector<R> clusterReads = {R::Lights, R::Camera, R::GBuffer};
    if (blended) clusterReads.push_back(R::Geometry);  // the BLEND surfaces occupy clusters too
    // Shadow views leave out the planar casters that hide no visible surface: the occupancy finds their sides.
    const bool drawsShadows = shadows && !unlit;
    passes.push_back({"cluster", clusterReads, {R::ClusterLists}, [this, &t, blended, drawsShadows, clustered,
                                                                   settings = options.shadows,
                                                                   stats = options.stats] {
                        const BlendedSurfaces surfaces = blendedSurfaces(t.blendTarget.id());
                        // Only a frame that draws its maps asks which sides of the caster planes its surfaces
                        // lie on: one that keeps them skips the test's cost.
                        const bool drawsMaps = drawsShadows && !(settings.cache && scene_.shadows.holds(
                                                                     shadowFrameKey(settings, clustered)));
                        t.clusters.setCasterPlanes(drawsMaps ? scene_.geometry.casterPlanes(sceneData_)
                                                             : std::vector<CasterPlane>{},
                                                   frameData_.inverseView);
                        markCulling(CullingChoice::ClusterBegin);
                        t.clusters.assign(frameData_, frame_, scene_.lights, t.gbuffer.depth,
                                          blended ? &surfaces : nullptr, stats);
                        markCulling(CullingChoice::ClusterEnd);
                      }});
  }
  // After the cluster pass: the shadow views are planned from the clusters the surfaces occupy.
  if (shadows && !unlit) {
    std::vector<R> shadowReads = {R::Geometry, R::Lights, R::Camera, R::GBuffer};
    if (clustered) shadowReads.push_back(R::ClusterLists);
    passes.push_back({"shadow", shadowReads, {R::ShadowMaps},
                      [this, settings = options.shadows, clustered] { renderShadows(settings, clustered); }});
  }
  std::vector<R> lightingReads = {R::GBuffer, R::Radiance, R::Lights, R::Camera};
  if (clustered) lightingReads.push_back(R::ClusterLists);
  if (ibl) lightingReads.push_back(R::Environment);
  if (shadows) lightingReads.push_back(R::ShadowMaps);
  std::vector<R> lightingWrites = {R::Radiance};
  if (efficiency) lightingWrites.push_back(R::PairCounts);
  if (shadowView) lightingWrites.push_back(R::ShadowLight);
  // The emission channel is post's picture of the radiance target as the geometry pass leaves it, emission alone:
  // leaving lighting out shows it without a copy of the target, and with the frame's own exposure and tone map.
  if (!unlit) {
    passes.push_back({"lighting", lightingReads, lightingWrites, [this, &t, options, clustered, ibl, efficiency,
                                                                  shadows, shadowView] {
                        const SurfaceTextures surface = surfaceTextures(t.gbuffer);
                        const EnvironmentMaps maps = ibl ? scene_.ibl->maps() : EnvironmentMaps{};
                        const ShadowMaps shadowMaps = scene_.shadows.maps();
                        const LightingOptions lighting{options.model,
                                                       options.variant,
                                                       sceneData_.ambient,
                                                       options.stats,
                                                       ibl ? &maps : nullptr,
                                                       efficiency ? &t.pairCounts() : nullptr,
                                                       shadows ? &shadowMaps : nullptr,
                                                       options.shadows.filter,
                                                       shadowView ? &t.shadowLight() : nullptr,
                                                       scene_.geometry.hasUnlit(),
                                                       t.gbuffer.layout.specular && options.lobes.specular,
                                                       t.gbuffer.layout.clearcoat && options.lobes.clearcoat,
                                                       t.gbuffer.layout.sheen && options.lobes.sheen};
                        const bool chunked = scene_.lighting.needsLightChunks(scene_.lights.count(), clustered);
                        const Texture* partial = chunked ? &t.partialRadiance() : nullptr;
                        markCulling(CullingChoice::LightingBegin);
                        scene_.lighting.render(surface, scene_.lights, lighting, frame_, t.hdr,
                                               clustered ? &t.clusters : nullptr, partial);
                        markCulling(CullingChoice::LightingEnd);
                      }});
  }
  if (blended && !emission && !replacesDisplay) {
    std::vector<R> reads = lightingReads;
    reads.push_back(R::Geometry);
    passes.push_back({"transparency", reads, {R::Radiance}, [this, &t, options, clustered, ibl, shadows] {
                        const EnvironmentMaps maps = ibl ? scene_.ibl->maps() : EnvironmentMaps{};
                        const ShadowMaps shadowMaps = scene_.shadows.maps();
                        LightingOptions lighting;
                        lighting.model = options.model;
                        lighting.variant = options.variant;
                        lighting.ambient = sceneData_.ambient;
                        lighting.environment = ibl ? &maps : nullptr;
                        lighting.shadows = shadows ? &shadowMaps : nullptr;
                        lighting.shadowFilter = options.shadows.filter;
                        const GBufferLayout& extensions = scene_.geometry.blendedExtensions();
                        lighting.specularMaterials = extensions.specular && options.lobes.specular;
                        lighting.clearcoatMaterials = extensions.clearcoat && options.lobes.clearcoat;
                        lighting.sheenMaterials = extensions.sheen && options.lobes.sheen;
                        lighting.transmissionOff = !options.lobes.transmission;
                        OitTargets oit;
                        GLuint target = t.blendTarget.id();
                        if (options.transparency == Transparency::Oit) {
                          const FrameTargets::OrderIndependent& weighted = t.orderIndependent();
                          oit.accumulation = &weighted.accumulation;
                          oit.revealage = &weighted.revealage;
                          target = weighted.framebuffer.id();
                        } else if (options.transparency == Transparency::Exact) {
                          oit.layerLists = &t.layerLists();
                        }
                        const BlendedSurfaces transmissive = blendedSurfaces(t.blendTarget.id());
                        TransmissionTargets transmission;
                        if (scene_.geometry.hasTransmissive()) {
                          transmission.surfaces = &transmissive;
                          transmission.background = &t.transmissionBackground();
                        }
                        scene_.lighting.renderBlended(blendedSurfaces(target), transmission, scene_.lights, lighting,
                                                      frame_, t.hdr, clustered ? &t.clusters : nullptr, oit);
                      }});
  }
  // A debug channel other than the cluster views replaces the display image: nothing to anti-alias. The cluster
  // views are painted after anti-aliasing, so that their legend is never filtered.
  const bool antiAliased = options.aa == AntiAliasing::Fxaa && (!debug || source == DebugSource::ClusterGrid);
  const bool metered = options.autoExposure && options.model == ShadingModel::Pbr && !replacesDisplay;
  if (metered) {
    passes.push_back({"exposure", {R::Radiance}, {R::Exposure}, [this, &t, options] {
                        const float initialEv100 = float(ev100FromExposure(options.exposure));
                        exposureMeter().meter(t.hdr, options.adaptSeconds, initialEv100);
                      }});
  }
  if (!replacesDisplay) {
    std::vector<R> reads = {R::Radiance};
    if (metered) reads.push_back(R::Exposure);
    passes.push_back({"post", reads, {R::Display}, [this, &t, options, antiAliased, metered] {
                        const Texture& display = antiAliased ? t.beforeAntiAliasing() : t.ldr;
                        scene_.post.render(t.hdr, display,
                                           {options.exposure, options.model == ShadingModel::Pbr, options.toneCurve,
                                            metered ? &exposureMeter() : nullptr});
                      }});
  }
  if (antiAliased) {
    passes.push_back({"aa", {R::Display}, {R::Display}, [this, &t] { scene_.fxaa.render(t.beforeAntiAliasing(), t.ldr); }});
  }
  if (debug) passes.push_back(debugPass(*options.debug));
  if (capture.ldr || capture.hdr) {
    std::vector<R> reads;
    if (capture.ldr) reads.push_back(R::Display);
    if (capture.hdr) reads.push_back(R::Radiance);
    passes.push_back({"readback", reads, {R::Capture}, [&t, capture] {
                        if (capture.ldr) *capture.ldr = readbackRgba8(t.ldr);
                        if (capture.hdr) *capture.hdr = readbackRgbaF(t.hdr);
                      }});
  }
  checkPassList(passes);
  return passes;
}

void Renderer::captureFrame(int frame, const FrameCapturer& capturer) {
  captureFrame_ = frame;
  capturer_ = &capturer;
}

FramePass Renderer::debugPass(DebugChannel channel) {
  using R = FrameResource;
  FrameTargets& t = *targets_;
  const DebugSource source = debugChannelInfo(channel).source;
  std::vector<R> reads;
  switch (source) {
    case DebugSource::Emission: reads = {R::Display, R::Camera}; break;
    case DebugSource::Surface: reads = {R::GBuffer, R::Camera}; break;
    case DebugSource::ClusterGrid: reads = {R::ClusterLists, R::GBuffer, R::Camera, R::Display}; break;
    case DebugSource::ShadowLight: reads = {R::ShadowLight, R::ShadowMaps, R::Camera}; break;
    case DebugSource::Layers: reads = {R::Geometry, R::GBuffer, R::Camera}; break;
    case DebugSource::PairCounts: reads = {R::PairCounts, R::Camera}; break;
  }
  return {"debug", reads, {R::Display}, [this, &t, channel, source] {
            scene_.debugLegend.update(makeLegendBlock(legendText(channel, frameData_, t.clusters.dims().z)));
            switch (source) {
              case DebugSource::Surface:
              case DebugSource::Emission: {
                const SurfaceTextures surface = surfaceTextures(t.gbuffer);
                scene_.gbufferDebug.render(channel, surface, frame_, scene_.debugLegend, t.ldr);
                break;
              }
              case DebugSource::ClusterGrid:
                scene_.clusterDebug.render(channel, t.clusters, t.gbuffer.depth, frame_, scene_.debugLegend, t.ldr);
                break;
              case DebugSource::Layers: {
                const FrameTargets::LayerCount& count = t.layerCount();
                scene_.transparencyDebug.render(blendedSurfaces(count.framebuffer.id()), count.layers, frame_,
                                                scene_.debugLegend, t.ldr);
                break;
              }
              case DebugSource::ShadowLight:
                scene_.shadowDebug.render(t.shadowLight(), scene_.shadows.maps(), scene_.shadows.ownerMap(), frame_,
                                          scene_.debugLegend, t.ldr);
                break;
              case DebugSource::PairCounts:
                scene_.efficiencyDebug.render(t.pairCounts(), frame_, scene_.debugLegend, t.ldr);
                break;
            }
          }};
}

void Renderer::markCulling(CullingChoice::Mark at) {
  if (cullingTimed_) cullingChoice_.mark(at);
  if (tileTimed_ && at == CullingChoice::ClusterBegin) tileTrials_.mark(TileTrials::Begin);
  if (tileTimed_ && at == CullingChoice::LightingEnd) tileTrials_.mark(TileTrials::End);
}

// What the cost of a light-pixel pair depends on: a change starts the measurements again.
std::string Renderer::costKey(const FrameOptions& options) const {
  return std::string(toString(options.model)) + "|" + toString(options.variant) + "|" +
         toString(options.shadows.mode) + "|" + toString(options.shadows.filter) + "|" +
         std::to_string(options.shadows.atlasSize) + "|" + std::to_string(width()) + "x" + std::to_string(height());
}

bool Renderer::tileTrialsPending() const { return tileTrialsRan_ && !tileTrials_.decided(); }

void Renderer::chooseTile(const FrameOptions& options) {
  tileTimed_ = false;
  tileTrialsRan_ = false;
  // Frames with a debug channel keep the grid as it is: the cluster views show it, the others time nothing.
  if (!config_.clusters.tileTrial || options.culling == Culling::None || options.debug) return;
  LightClusters& clusters = targets_->clusters;
  const uint32_t lights = scene_.lights.count();
  clusters.setTileSize(tileTrials_.tile(costKey(options) + "|" + std::to_string(lights), config_.clusters.tileSize,
                                        clusters.settled(lights), clusters.recentListLength()));
  tileTimed_ = tileTrials_.timing();
  tileTrialsRan_ = true;
}

FrameOptions Renderer::resolveCulling(const FrameOptions& options) {
  FrameOptions resolved = options;
  cullingTimed_ = false;
  lastDecision_.reset();
  if (options.culling != Culling::Auto) return resolved;
  // The cluster views show the clusters' lists: those frames run clustered, untimed.
  if (options.debug && needsClusterGrid(*options.debug)) {
    resolved.culling = Culling::Clustered;
    return resolved;
  }
  const CullingCounts counts{scene_.lights.count(), uint64_t(width()) * uint64_t(height()),
                             targets_->clusters.recentListLength()};
  // Frames run clustered while the grid's tile side is being timed.
  const bool settled = targets_->clusters.settled(scene_.lights.count()) && !tileTrialsPending();
  resolved.culling = cullingChoice_.choose(costKey(options), counts, settled);
  lastDecision_ = cullingChoice_.decision();
  cullingTimed_ = true;
  return resolved;
}

void Renderer::renderFrame(const FrameOptions& requested, Profiler& profiler, const FrameCapture& capture) {
  chooseTile(requested);
  const FrameOptions options = resolveCulling(requested);
  const PassList passes = passList(options, capture);
  std::optional<CapturedFrame> captured;
  if (++framesRendered_ == captureFrame_ && capturer_) captured.emplace(*capturer_, framesRendered_);
  profiler.beginFrame();
  runPassList(passes, profiler);
  profiler.endFrame();
  cullingTimed_ = false;
  lastOptions_ = options;
  lastShadowed_ = std::any_of(passes.begin(), passes.end(), [](const FramePass& p) { return p.name == "shadow"; });
  lastMetered_ = std::any_of(passes.begin(), passes.end(), [](const FramePass& p) { return p.name == "exposure"; });
}

ExposureMeter& Renderer::exposureMeter() {
  if (!scene_.exposureMeter) scene_.exposureMeter = std::make_unique<ExposureMeter>(scene_.programs);
  return *scene_.exposureMeter;
}

void Renderer::restartExposure(float exposure) { exposureMeter().reset(float(ev100FromExposure(exposure))); }

std::optional<MeteredExposure> Renderer::meteredExposure() const {
  if (!lastMetered_) return std::nullopt;
  return scene_.exposureMeter->read();
}

RendererCounters Renderer::counters() const {
  return {targetBuilds_, scene_.programs.compiled(), gpuMeshUploads(), gpuTextureUploads()};
}

WarmUpReport Renderer::warmUp(const FrameOptions& options, Profiler& profiler, int frames) {
  WarmUpReport report;
  for (; report.frames < frames; ++report.frames) renderFrame(options, profiler);
  // Timed frames should not be the trials of culling auto (a brute-force trial can cost many clustered frames).
  constexpr int kMaxCullingFrames = 40;
  while (((lastDecision_ && !cullingChoice_.decided()) || tileTrialsPending()) &&
         report.cullingFrames < kMaxCullingFrames) {
    renderFrame(options, profiler);
    ++report.frames;
    ++report.cullingFrames;
  }
  if (lastOptions_.culling != Culling::Clustered) return report;
  // Light lists only grow: a few rounds fit any static frame; the bound guards against a list at its limit.
  constexpr int kMaxSizingFrames = 4;
  while (report.listSizingFrames < kMaxSizingFrames && targets_->clusters.growToDemand()) {
    renderFrame(options, profiler);
    ++report.frames;
    ++report.listSizingFrames;
  }
  report.overflowedClusters = targets_->clusters.readStatus().overflowed;
  return report;
}

LightStats Renderer::lightStats() const {
  LightStats s;
  s.lights = scene_.lights.count();
  if (lastOptions_.culling == Culling::Clustered) {
    const LightClusters& clusters = targets_->clusters;
    const ClusterStatus status = clusters.readStatus();
    const glm::uvec3 d = clusters.dims();
    s.clusters = d.x * d.y * d.z;
    s.tileSize = uint32_t(clusters.tileSize());
    s.activeClusters = status.activeClusters;
    s.nonEmptyClusters = status.nonEmpty;
    s.maxPerCluster = status.maxPerCluster;
    s.indexEntries = status.demand;
    s.overflowedClusters = status.overflowed;
    s.visibleLights = status.visibleLights;
  }
  if (lastOptions_.stats) s.pairs = scene_.lighting.readPairCounts();
  if (lastShadowed_) {
    s.shadows = scene_.shadows.stats();
    s.shadows.readBackMs = shadowReadBackMs_;
    s.shadows.drawsPerLight = shadowDrawsPerLight_;
  }
  s.culling = lastOptions_.culling;
  s.decision = lastDecision_;
  const Buffer* lists = targets_->layerListsIfMade();
  if (lastOptions_.transparency == Transparency::Exact && lists) s.droppedLayers = readDroppedLayers(*lists);
  return s;
}

}  // namespace pbr
