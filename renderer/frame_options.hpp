#pragma once
#include <cstdint>
#include <limits>
#include <optional>

#include "core/scene/shading_model.hpp"
#include "core/scene/shadow_settings.hpp"
#include "core/scene/tone_curve.hpp"
#include "core/scene/transparency.hpp"
#include "debug/debug_channel.hpp"
#include "lighting/lighting_options.hpp"
#include "post/anti_aliasing.hpp"
#include "renderer/culling_decision.hpp"
#include "shadows/shadow_plan.hpp"

// What a frame is rendered with and what it reports, with no GL: Renderer::renderFrame takes them (renderer.hpp).
namespace pbr {

// The culling `pbr render`, `view` and `bench` start from; a FrameOptions made in code starts from Clustered.
constexpr Culling kCommandCulling = Culling::Auto;

struct FrameOptions {
  ShadingModel model = ShadingModel::Pbr;
  ShadingVariant variant;  // PBR only
  Culling culling = Culling::Clustered;
  float exposure = 1.0f;
  bool stats = false;  // GPU counters for the light statistics (costs time; off for timing runs)
  // A debug channel in place of the final frame, with its legend. Clusters and slices are painted over the
  // (anti-aliased) frame and need clustered culling; the others replace the frame, which is then not anti-aliased.
  std::optional<DebugChannel> debug;
  AntiAliasing aa = AntiAliasing::None;  // of the display image, before any debug view
  ShadowSettings shadows;                // a frame none of whose lights casts runs no shadow pass
  Transparency transparency = Transparency::Sorted;  // of BLEND surfaces; a frame without any runs no such pass
  ToneCurve toneCurve = ToneCurve::AcesHill;         // of PBR frames' display transform
  // PBR frames: the exposure metered from the frame itself (post/exposure_meter.hpp) in place of `exposure`, which
  // sets it only before anything is metered. It moves toward each frame's metering over `adaptSeconds` (the time
  // since the last frame); infinite, the headless default, applies each frame's own metering.
  bool autoExposure = false;
  float adaptSeconds = std::numeric_limits<float>::infinity();
  MaterialLobes lobes;  // the material extensions' lobes shaded (all, unless one is switched off to compare)
};

// Light statistics of the last frame. Cluster figures are zero with culling none; visible lights and pair
// counts need FrameOptions::stats.
struct LightStats {
  uint32_t lights = 0;
  uint32_t visibleLights = 0;       // lights touching at least one cluster (frustum-culled survivors)
  uint32_t clusters = 0;
  uint32_t tileSize = 0;            // the cluster grid's tile side in pixels (--tile auto times it)
  uint32_t activeClusters = 0;     // clusters holding a surface: the only ones given lights
  uint32_t nonEmptyClusters = 0;
  uint32_t maxPerCluster = 0;
  uint64_t indexEntries = 0;        // entries of the light-index list the frame needed
  uint32_t overflowedClusters = 0;  // shaded by brute force: the list or the light masks were full
  PairCounts pairs;
  ShadowStats shadows;              // of the last frame's shadow pass; zero without one
  // BLEND fragments the last frame's exact transparency left out (kLayerNodesPerPixel).
  uint32_t droppedLayers = 0;
  Culling culling = Culling::Clustered;     // the path the last frame ran
  std::optional<CullingDecision> decision;  // with --culling auto: why
  double averagePerNonEmpty() const { return nonEmptyClusters ? double(indexEntries) / nonEmptyClusters : 0.0; }
  // Light-pixel pairs that contribute over pairs evaluated.
  double cullingEfficiency() const { return pairs.evaluated ? double(pairs.contributing) / pairs.evaluated : 0.0; }
};

}  // namespace pbr
