#include "app/renderer.hpp"

#include "app/frame_limits.hpp"
#include "core/readback.hpp"

namespace pbr {

namespace {

Environment loadEnvironment(const EnvironmentDesc& e) {
  return e.file.empty() ? Environment::sky(e.sky, e.intensity, e.rotationDeg)
                        : Environment::fromHdrFile(e.file, e.intensity, e.rotationDeg);
}

// Called while width_ is initialised, before any member allocates a target: an impossible size fails here.
int checkedWidth(int width, int height, const RendererConfig& config) {
  checkFrameSize(width, height, config.sizeOption, frameBytesPerPixel(config), queryFrameLimits());
  checkFrameFormats(width, height, config.sizeOption, frameFormats(config));
  return width;
}

}  // namespace

Renderer::Renderer(const ShaderLibrary& shaders, const Scene& scene, int width, int height,
                   const RendererConfig& config)
    : scene_(scene),
      width_(checkedWidth(width, height, config)),
      height_(height),
      frameData_(makeFrameBlock(scene.camera, width, height)),
      frame_(frameData_),
      hdr_(glInternalFormat(config.hdrFormat), width, height),
      gbuffer_(width, height, hdr_, config.gbuffer),
      gbufferPass_(shaders, scene),
      clusters_(shaders, config.clusters),
      lightingPass_(shaders),
      postPass_(shaders),
      debugPass_(shaders),
      ldr_(GL_RGBA8, width, height) {
  lights_.upload(scene.lights);
  if (scene.environment) {
    ibl_ = std::make_unique<IblMaps>(shaders, loadEnvironment(*scene.environment), IblSettings{}, config.precomputeProfiler);
  }
}

void Renderer::setCamera(const Camera& camera) {
  frameData_ = makeFrameBlock(camera, width_, height_);
  frame_.update(frameData_);
}

void Renderer::renderFrame(const FrameOptions& options, Profiler& profiler, const FrameCapture& capture) {
  profiler.beginFrame();
  {
    ScopedPass pass(profiler, "gbuffer");
    gbufferPass_.render(gbuffer_, frame_);
  }
  const bool clustered = options.culling == Culling::Clustered;
  if (clustered) {
    ScopedPass pass(profiler, "cluster");
    clusters_.assign(frameData_, frame_, lights_, options.stats);
  }
  {
    ScopedPass pass(profiler, "lighting");
    const SurfaceTextures surface{gbuffer_.baseColor, gbuffer_.normal, gbuffer_.material, gbuffer_.depth};
    const bool ibl = ibl_ && options.model == ShadingModel::Pbr;
    const LightingOptions lighting{options.model, options.variant, scene_.ambient, options.stats, ibl};
    if (ibl) ibl_->bind();
    lightingPass_.render(surface, lights_, lighting, frame_, hdr_, clustered ? &clusters_ : nullptr);
  }
  {
    ScopedPass pass(profiler, "post");
    postPass_.render(hdr_, ldr_, {options.exposure, options.model == ShadingModel::Pbr});
  }
  if (clustered && options.debugView != ClusterDebugView::None) {
    ScopedPass pass(profiler, "debug");
    debugPass_.render(options.debugView, clusters_, gbuffer_.depth, frame_, ldr_);
  }
  if (capture.ldr || capture.hdr) {
    ScopedPass pass(profiler, "readback");
    if (capture.ldr) *capture.ldr = readbackRgba8(ldr_);
    if (capture.hdr) *capture.hdr = readbackRgbaF(hdr_);
  }
  profiler.endFrame();
  lastOptions_ = options;
}

WarmUpReport Renderer::warmUp(const FrameOptions& options, Profiler& profiler, int frames) {
  WarmUpReport report;
  for (; report.frames < frames; ++report.frames) renderFrame(options, profiler);
  if (options.culling != Culling::Clustered) return report;
  // Light lists only grow: a few rounds fit any static frame; the bound guards against a list at its limit.
  constexpr int kMaxSizingFrames = 4;
  while (report.listSizingFrames < kMaxSizingFrames && clusters_.growToDemand()) {
    renderFrame(options, profiler);
    ++report.frames;
    ++report.listSizingFrames;
  }
  report.overflowedClusters = clusters_.readStatus().overflowed;
  return report;
}

LightStats Renderer::lightStats() const {
  LightStats s;
  s.lights = lights_.count();
  if (lastOptions_.culling == Culling::Clustered) {
    const ClusterStatus status = clusters_.readStatus();
    const glm::uvec3 d = clusters_.dims();
    s.clusters = d.x * d.y * d.z;
    s.nonEmptyClusters = status.nonEmpty;
    s.maxPerCluster = status.maxPerCluster;
    s.indexEntries = status.demand;
    s.overflowedClusters = status.overflowed;
    s.visibleLights = status.visibleLights;
  }
  if (lastOptions_.stats) s.pairs = lightingPass_.readPairCounts();
  return s;
}

}  // namespace pbr
