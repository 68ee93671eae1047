#pragma once
#include <cstdint>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "core/scene/bounds.hpp"
#include "core/scene/camera.hpp"
#include "core/scene/caster_plane.hpp"
#include "core/scene/scene.hpp"
#include "core/scene/shadow_settings.hpp"
#include "shadows/shadow_receivers.hpp"

namespace pbr {

// What a frame's shadows are planned from: the camera, the frame's height, the lights, the casters' bounds and the
// visible surfaces (receivers) the cluster occupancy found.
struct ShadowInputs {
  const Camera& camera;
  float aspect;
  int frameHeight;  // pixels: a light's size on screen sets its maps' resolution
  const std::vector<PointLight>& lights;       // scene order
  const std::vector<uint32_t>& bufferOrder;    // per light-buffer index, the scene's index of the light there
  const std::vector<DirectionalLight>& directional;
  WorldBounds scene;  // every object's: the casters a cascade must hold
  const ShadowReceivers& receivers;
  ShadowMode mode = ShadowMode::Auto;
  int atlasSize = 4096;
  // The planar casters' planes and the sides of them the visible surfaces lie on (receiversAbove/Below): a light's
  // views leave out the planes that hide none of those surfaces from it.
  std::vector<CasterPlane> casterPlanes{};
  uint32_t planeSides = 0;
};

// One square of the atlas, rendered from a light. `size` 0: not rendered, its frustum meets no receiver in view.
struct ShadowViewPlan {
  glm::mat4 viewProjection{1.0f};
  glm::ivec2 origin{0};  // atlas texels
  int size = 0;
  float texelWorld = 0.0f;  // world size of a texel per unit of the view's w (ShadowCasterView::texelWorld)
  glm::vec4 reach{0.0f};  // ShadowCasterView::reach
  uint32_t light = 0;     // which of the plan's shadowed lights owns it, counting from 0 (the debug view's colours)
  uint32_t skipPlanes = 0;  // ShadowCasterView::skipPlanes
};

// What planShadows decided, for `--stats` and the profiler's light statistics.
struct ShadowStats {
  uint32_t shadowedLights = 0;   // lights with maps (point, spot and directional)
  uint32_t viewsRendered = 0;    // cube faces, spot views and cascades in the maps (drawn this frame unless reused)
  uint32_t viewsSkipped = 0;     // of those lights' views, left out: no receiver in view in their frustum
  uint32_t viewsKept = 0;        // of viewsRendered, kept from the frame before (ShadowPass::render's keepViews)
  uint32_t shrunkLights = 0;     // lights given less than their size on screen asks, the atlas being full
  uint32_t unshadowedLights = 0; // casting lights that got no map at all, the atlas being full at the least size
  uint64_t texelsUsed = 0;       // atlas texels of the rendered views
  uint32_t planesLeftOut = 0;    // planar casters left out of rendered views, one per view and plane
  // World size of a texel of the rendered cascades, finest and coarsest (0 without one).
  float cascadeTexelMin = 0.0f, cascadeTexelMax = 0.0f;
  // The pass's CPU side in the last frame, wall-clock ms: reading the occupied clusters back (a wait for the GPU)
  // and building the receivers, planning, and recording the clears and draws; and the draw calls recorded.
  double readBackMs = 0.0, planMs = 0.0, recordMs = 0.0;
  uint32_t draws = 0;
  uint32_t oneSidedDraws = 0;  // of them, closed casters drawn from their faces toward the light alone
  bool drawsPerLight = false;  // ShadowDraws::PerLight ran
  bool reused = false;         // the maps are an earlier frame's: nothing they depend on changed (ShadowFrameKey)
};

// The frame's shadow views and, per light, which views it owns: what the GPU buffers are made from (the header, whose
// directional entries here name views, the lights' entries) and the squares to render.
struct ShadowPlan {
  std::vector<ShadowViewPlan> views;
  std::vector<uint32_t> lightViews;  // per light-buffer index
  GpuShadowHeader header{};
  ShadowStats stats;
  bool any() const { return stats.shadowedLights > 0; }
};

// Least and largest side of a light's square, in texels; cascades take a quarter of the atlas's side each.
constexpr int kMinShadowView = 16;
constexpr int kMaxShadowView = 1024;
constexpr int kCascades = 4;

// Plans a frame's shadows (Olsson et al. 2014, "Efficient Virtual Shadow Maps for Many Lights", in outline): each
// casting light's resolution from its size on screen; cube faces and spot views whose frustum, bounded by the
// light's radius, holds no visible receiver (an occupied cluster) are not rendered; directional lights get kCascades texel-snapped cascades over the view depths
// that hold receivers, a cascade whose depths hold none not rendered. When the atlas cannot hold every square, the
// least important lights (smallest on screen) are halved first; a light left without a square is counted, never
// silently dropped.
ShadowPlan planShadows(const ShadowInputs& inputs);

// Whether any light of the frame casts under `mode`.
bool anyShadowCaster(const std::vector<PointLight>& lights, const std::vector<DirectionalLight>& directional,
                     ShadowMode mode);

// Bytes of an atlas of `size` x `size` 32-bit depth texels.
inline uint64_t shadowAtlasBytes(int size) { return uint64_t(size) * uint64_t(size) * 4u; }

}  // namespace pbr
