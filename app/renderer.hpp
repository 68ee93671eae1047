#pragma once
#include <memory>
#include <string>

#include "core/frame_block.hpp"
#include "core/image.hpp"
#include "core/profiler.hpp"
#include "core/scene.hpp"
#include "core/shader_library.hpp"
#include "core/uniform_buffer.hpp"
#include "gbuffer/gbuffer.hpp"
#include "gbuffer/gbuffer_pass.hpp"
#include "ibl/ibl_maps.hpp"
#include "lighting/cluster_debug_pass.hpp"
#include "lighting/lighting_pass.hpp"
#include "post/post_pass.hpp"

namespace pbr {

struct FrameOptions {
  ShadingModel model = ShadingModel::Pbr;
  ShadingVariant variant;  // PBR only
  Culling culling = Culling::Clustered;
  float exposure = 1.0f;
  bool stats = false;  // GPU counters for the light statistics (costs time; off for timing runs)
  ClusterDebugView debugView = ClusterDebugView::None;  // painted over the final frame (clustered only)
};

// Light statistics of the last frame. Cluster figures are zero with culling none; visible lights and pair
// counts need FrameOptions::stats.
struct LightStats {
  uint32_t lights = 0;
  uint32_t visibleLights = 0;       // lights touching at least one cluster (frustum-culled survivors)
  uint32_t clusters = 0;
  uint32_t nonEmptyClusters = 0;
  uint32_t maxPerCluster = 0;
  uint64_t indexEntries = 0;        // entries of the light-index list the frame needed
  uint32_t overflowedClusters = 0;  // shaded by brute force because the list was full
  PairCounts pairs;
  double averagePerNonEmpty() const { return nonEmptyClusters ? double(indexEntries) / nonEmptyClusters : 0.0; }
  // Light-pixel pairs that contribute over pairs evaluated.
  double cullingEfficiency() const { return pairs.evaluated ? double(pairs.contributing) / pairs.evaluated : 0.0; }
};

// Images to read back at the end of a frame (timed as the "readback" pass); null members are skipped.
struct FrameCapture {
  ImageRgba8* ldr = nullptr;
  ImageRgbaF* hdr = nullptr;  // radiance before exposure, as the lighting pass wrote it
};

// What a renderer is built with, beyond the scene and the frame size.
struct RendererConfig {
  ClusterConfig clusters;
  HdrFormat hdrFormat = HdrFormat::Rgba16f;
  GBufferPrecision gbuffer = GBufferPrecision::Lean;
  Profiler* precomputeProfiler = nullptr;  // times the IBL precomputation when the scene has an environment
  std::string sizeOption = "--size";       // the option the frame size came from, named when it is too large
};

// What Renderer::warmUp did before the timed frames.
struct WarmUpReport {
  int frames = 0;            // untimed frames rendered
  int listSizingFrames = 0;  // of those, frames added because a cluster's light list did not fit yet
  uint32_t overflowedClusters = 0;  // clusters still shaded by brute force after warm-up (list at its limit)
};

// The whole frame: G-buffer -> deferred lighting (HDR, RGBA16F by default) -> post (RGBA8), with each pass timed.
class Renderer {
 public:
  // A scene with an environment has its IBL maps precomputed here, once; with config.precomputeProfiler that is
  // one profiler frame of its own (ibl/README.md), so the profiler must not be inside a frame. Throws
  // std::runtime_error naming the file when the environment's .hdr cannot be used, and naming config.sizeOption
  // when the frame is over the context's texture size or the memory available (app/frame_limits.hpp), before any
  // target is allocated.
  Renderer(const ShaderLibrary& shaders, const Scene& scene, int width, int height, const RendererConfig& config = {});

  void renderFrame(const FrameOptions& options, Profiler& profiler, const FrameCapture& capture = {});
  // After at least one frame: renders `frames` more untimed frames, then, with clustered culling, more until every cluster's light
  // list fits (each grows the list at once to the measured demand), so that no timed frame pays for a list sized
  // a frame late. Stops early when the list has reached its memory limit: the report says how many clusters
  // still fall back to brute force.
  WarmUpReport warmUp(const FrameOptions& options, Profiler& profiler, int frames);

  // For interactive use: a moved camera rebuilds the frame block (cluster bounds follow when the projection
  // changes); new lights replace the light buffer.
  void setCamera(const Camera& camera);
  void setLights(const std::vector<PointLight>& lights) { lights_.upload(lights); }

  // Reads the GPU counters of the last frame; waits for the GPU.
  LightStats lightStats() const;
  const LightClusters& clusters() const { return clusters_; }
  const LightBuffer& lights() const { return lights_; }
  const GBuffer& gbuffer() const { return gbuffer_; }
  const IblMaps* ibl() const { return ibl_.get(); }  // null without an environment
  const UniformBuffer<FrameBlock>& frameUniforms() const { return frame_; }
  const Texture& ldr() const { return ldr_; }  // the final RGBA8 frame, rows bottom-up as GL stores them

  int width() const { return width_; }
  int height() const { return height_; }

 private:
  const Scene& scene_;
  int width_, height_;
  FrameBlock frameData_;
  UniformBuffer<FrameBlock> frame_;
  Texture hdr_;  // radiance: emission from the G-buffer pass, then reflected light from the lighting pass
  GBuffer gbuffer_;
  GBufferPass gbufferPass_;
  LightBuffer lights_;
  LightClusters clusters_;
  LightingPass lightingPass_;
  std::unique_ptr<IblMaps> ibl_;
  FrameOptions lastOptions_;
  PostPass postPass_;
  ClusterDebugPass debugPass_;
  Texture ldr_;
};

}  // namespace pbr
