#pragma once
#include <memory>
#include <optional>
#include <string>

#include "core/gl/frame_capture.hpp"
#include "core/gl/profiler.hpp"
#include "core/gl/shader_library.hpp"
#include "core/gl/uniform_buffer.hpp"
#include "core/scene/frame_block.hpp"
#include "core/scene/image.hpp"
#include "core/scene/scene.hpp"
#include "core/scene/shadow_settings.hpp"
#include "debug/debug_channel.hpp"
#include "renderer/culling_choice.hpp"
#include "renderer/frame_options.hpp"
#include "renderer/frame_targets.hpp"
#include "renderer/pass_list.hpp"
#include "renderer/renderer_config.hpp"
#include "renderer/scene_resources.hpp"
#include "renderer/tile_trials.hpp"

namespace pbr {

// Images to read back at the end of a frame (timed as the "readback" pass); null members are skipped.
struct FrameCapture {
  ImageRgba8* ldr = nullptr;
  ImageRgbaF* hdr = nullptr;  // radiance before exposure, as the lighting pass wrote it
};

// What Renderer::warmUp did before the timed frames.
struct WarmUpReport {
  int frames = 0;            // untimed frames rendered
  int listSizingFrames = 0;  // of those, frames added because a cluster's light list did not fit yet
  int cullingFrames = 0;     // of those, frames added until culling auto and the tile side's trial had timed theirs
  uint32_t overflowedClusters = 0;  // clusters still shaded by brute force after warm-up (list or masks at their limit)
};

// What has been built so far, for checking that a resize rebuilds only what the size owns.
struct RendererCounters {
  int targetBuilds = 0;         // FrameTargets of this renderer
  size_t programsCompiled = 0;  // programs in the scene's cache
  size_t meshUploads = 0;       // meshes and textures uploaded by the whole process (gpuMeshUploads)
  size_t textureUploads = 0;
};

// The frame: scene resources (built once), frame targets (rebuilt on resize) and the pass list that runs over them
// (G-buffer -> cluster assignment -> deferred lighting -> post -> debug views -> read-back), each pass timed.
class Renderer {
 public:
  // A scene with an environment has its IBL maps precomputed here, once; with config.precomputeProfiler that is
  // one profiler frame of its own (ibl/README.md), so the profiler must not be inside a frame. Throws
  // std::runtime_error naming the file when the environment's .hdr cannot be used, and naming config.sizeOption
  // when the frame is over the context's texture size, the memory available or what the driver can create
  // (renderer/frame_limits.hpp, renderer/driver_limits.hpp), before any target is allocated. `scene` must outlive
  // the renderer.
  Renderer(const ShaderLibrary& shaders, const Scene& scene, int width, int height, const RendererConfig& config = {});

  // Replaces the frame targets at the new size; the scene's resources and compiled programs stay.
  void resize(int width, int height);

  // The passes one frame runs with these options, in order, each saying what it reads and writes.
  PassList passList(const FrameOptions& options, const FrameCapture& capture = {});
  void renderFrame(const FrameOptions& options, Profiler& profiler, const FrameCapture& capture = {});
  // After at least one frame: renders `frames` more untimed frames, then, with culling auto, more until it has
  // timed both paths, and while the grid's tile side is being timed (at most 40), then, with clustered culling,
  // more until every cluster's light list fits (each grows the list at once to the measured demand), so that no
  // timed frame pays for a list sized a frame late. Stops early when the list has reached its memory limit: the
  // report says how many clusters still fall back to brute force.
  WarmUpReport warmUp(const FrameOptions& options, Profiler& profiler, int frames);

  // Marks the `frame`-th frame this renderer renders (counting every renderFrame from 1, warm-up frames included)
  // for graphics debuggers, as `capturer` says (core/gl/frame_capture.hpp). `capturer` must outlive that frame.
  void captureFrame(int frame, const FrameCapturer& capturer);

  // For interactive use: a moved camera rebuilds the frame block (cluster bounds follow when the projection
  // changes); new point and spot lights replace those of the light buffer (the directional lights stay).
  void setCamera(const Camera& camera);
  void setLights(const std::vector<PointLight>& lights);
  // The scene's objects, lights and the meshes `changedMeshes` changed in place (posePlayback): uploaded again,
  // the point and spot lights replacing those of setLights.
  void scenePosed(const std::vector<int>& changedMeshes);

  // Reads the GPU counters of the last frame; waits for the GPU.
  LightStats lightStats() const;
  // The cluster grid's tile side and why (TileTrials::summary); empty where the side is not timed.
  std::string tileSummary() const { return config_.clusters.tileTrial ? tileTrials_.summary() : std::string(); }
  // What the automatic exposure applied to the last frame; waits for the GPU. None unless it ran that frame.
  std::optional<MeteredExposure> meteredExposure() const;
  // The automatic exposure adapts from `exposure` on the next frames, as after a switch from a fixed exposure.
  void restartExposure(float exposure);
  const LightClusters& clusters() const { return targets_->clusters; }
  const LightBuffer& lights() const { return scene_.lights; }
  const GBuffer& gbuffer() const { return targets_->gbuffer; }
  const IblMaps* ibl() const { return scene_.ibl.get(); }  // null without an environment
  const Texture& ldr() const { return targets_->ldr; }  // the final RGBA8 frame, rows bottom-up as GL stores them
  RendererCounters counters() const;

  int width() const { return targets_->width; }
  int height() const { return targets_->height; }

 private:
  // The "debug" pass of the list: what the channel reads, and the work.
  FramePass debugPass(DebugChannel channel);
  // Whether any light casts under `mode` (cached until the lights change).
  bool shadowed(ShadowMode mode);
  // The shadow pass: plans the views from where the surfaces are (the cluster occupancy) and renders them.
  // The scene's BLEND surfaces as the lighting module draws them (core/gl/blended_surfaces.hpp).
  // Drawn into `framebuffer`: the radiance target's or the order-independent targets', over the G-buffer's depth.
  BlendedSurfaces blendedSurfaces(GLuint framebuffer);
  void renderShadows(const ShadowSettings& settings, bool clustered);
  // What this frame's shadow maps depend on (ShadowFrameKey).
  ShadowFrameKey shadowFrameKey(const ShadowSettings& settings, bool clustered);
  // Whether the shadow casters are drawn a light's views at once (ShadowDraws); throws where PerLight is asked of a
  // driver without the extension it needs.
  bool shadowDrawsPerLight(ShadowDraws draws);
  // `options` with culling Auto replaced by this frame's choice (cullingChoice_), which its passes then time.
  FrameOptions resolveCulling(const FrameOptions& options);
  void markCulling(CullingChoice::Mark at);
  // The cluster grid's tile side for this frame (TileTrials, with ClusterConfig::tileTrial), set on the clusters.
  void chooseTile(const FrameOptions& options);
  bool tileTrialsPending() const;
  std::string costKey(const FrameOptions& options) const;
  // The automatic exposure's meter, made by the first frame or restart that needs it.
  ExposureMeter& exposureMeter();

  const Scene& sceneData_;
  RendererConfig config_;
  int targetBuilds_ = 1;
  SceneResources scene_;
  std::unique_ptr<FrameTargets> targets_;
  Camera camera_;
  FrameBlock frameData_;
  UniformBuffer<FrameBlock> frame_;
  std::vector<PointLight> lightsSet_;  // the lights of setLights, once called
  const std::vector<PointLight>* lights_;  // the frame's point and spot lights: the scene's or lightsSet_
  // Counted up by setLights and by scenePosed: what shadow maps drawn before were drawn for (ShadowFrameKey).
  uint64_t lightsVersion_ = 0, poseVersion_ = 0;
  std::optional<std::pair<ShadowMode, bool>> shadowedCache_;
  bool lastShadowed_ = false;
  double shadowReadBackMs_ = 0.0;  // the last shadow pass's occupancy read-back and receivers, CPU wall-clock
  bool shadowDrawsPerLight_ = false;        // the last shadow pass's ShadowDraws, resolved
  std::optional<bool> viewportFromVertex_;  // GL_ARB_shader_viewport_layer_array, asked once
  bool softwareRenderer_ = false;           // a CPU rasterizer (isSoftwareRenderer), asked with it
  bool lastMetered_ = false;  // the last frame ran the automatic exposure's meter
  FrameOptions lastOptions_;  // as the last frame ran them: culling Auto resolved
  CullingChoice cullingChoice_;
  std::optional<CullingDecision> lastDecision_;
  bool cullingTimed_ = false;  // this frame's cluster and lighting passes mark cullingChoice_
  TileTrials tileTrials_;
  bool tileTimed_ = false;      // this frame's cluster and lighting passes mark tileTrials_
  bool tileTrialsRan_ = false;  // this frame's tile side came from tileTrials_
  int framesRendered_ = 0;
  int captureFrame_ = 0;
  const FrameCapturer* capturer_ = nullptr;
};

}  // namespace pbr
