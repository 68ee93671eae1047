#pragma once
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "core/gl/gl_objects.hpp"
#include "core/gl/shadow_maps.hpp"
#include "core/scene/frame_block.hpp"
#include "shadows/shadow_plan.hpp"

namespace pbr {

// Draws the scene's casters' depth into `framebuffer`, once per view, into the views' squares: the renderer hands
// in the geometry pass's depth drawing, so that this pass knows no other.
// What a frame's maps depend on besides the scene's meshes and materials: the camera and frame size (views are sized
// from the screen and rendered only where they meet the visible surfaces), the lights and the objects' poses (which
// the renderer counts, `lightsVersion` whenever lights are set, `poseVersion` whenever objects move), the cluster
// grid whose occupancy says where the visible surfaces are, and the settings that shape the atlas. Two frames with
// equal keys have equal maps.
struct ShadowFrameKey {
  FrameBlock frame;
  uint64_t lightsVersion = 0;
  uint64_t poseVersion = 0;
  ShadowMode mode = ShadowMode::Auto;
  int atlasSize = 0;
  bool drawsPerLight = false;
  bool clustered = false;  // the occupancy came from the cluster pass, or from the occupancy pass alone
  int tileSize = 0;
  int slices = 0;
};
bool operator==(const ShadowFrameKey& a, const ShadowFrameKey& b);

using DrawShadowCasters =
    std::function<ShadowCasterDraws(GLuint framebuffer, const std::vector<ShadowCasterView>& views)>;

// The frame's shadow maps: plans them (planShadows), renders the planned squares into one depth atlas and uploads
// what the lighting pass reads (ShadowMaps). The atlas is allocated on the first shadowed frame, at the size the
// inputs ask, and again only when that size changes: a scene that shadows nothing never allocates one.
class ShadowPass {
 public:
  ShadowPass();
  // With `keepViews`, a view drawn into the same square the frame before, from the same matrix, with the same
  // reach, texel size and planes left out and with no object moved since, keeps its depths instead of being drawn
  // again: a light that did not move keeps its maps while the camera moves, as long as its squares stay where they
  // were and the visible surfaces keep to the same sides of the planes.
  void render(const ShadowInputs& inputs, const DrawShadowCasters& drawCasters, const ShadowFrameKey& key,
              bool keepViews);
  // Whether the last render's maps are those of a frame of `key` (its key was equal): then they stay, and the stats
  // say so; the frame skips reading the occupancy back, planning and drawing.
  bool reuse(const ShadowFrameKey& key);
  // Whether the atlas holds the maps of a frame of `key`, which reuse would keep.
  bool holds(const ShadowFrameKey& key) const { return renderedFor_ && *renderedFor_ == key; }
  // Valid after render.
  ShadowMaps maps() const;
  const ShadowStats& stats() const { return stats_; }
  // GPU bytes held: the atlas and the buffers.
  size_t bytes() const;
  // Which square each kMinShadowView-texel cell of the atlas belongs to, for the shadows debug view: RG32UI, view + 1
  // and light + 1 (ShadowViewPlan::light), 0 where no square lies. Made from the last render's plan on request.
  const Texture& ownerMap();

 private:
  std::unique_ptr<Texture> atlas_;
  std::unique_ptr<Framebuffer> framebuffer_;
  Sampler sampler_;
  std::unique_ptr<Buffer> views_;
  std::unique_ptr<Buffer> lightViews_;
  std::unique_ptr<Buffer> squares_;
  std::unique_ptr<Texture> owners_;
  std::vector<ShadowViewPlan> lastViews_;  // the last render's, for ownerMap
  bool ownersCurrent_ = false;
  ShadowStats stats_;
  std::optional<ShadowFrameKey> renderedFor_;  // the key of the frame the atlas holds
  std::vector<ShadowCasterView> atlasViews_;   // the views whose depths the atlas holds, by square
  // Texels that may hold a caster's depth (what renderDepth reported, less what was cleared since): the rest of the
  // atlas holds the far depth, so that a square need only have these cleared before it is drawn.
  std::vector<glm::ivec4> dirty_;
  // Clears the texels of the squares of `toDraw` that dirty_ says may hold depths, or the whole atlas where that is
  // cheaper and no view is kept.
  void clearSquares(const std::vector<ShadowCasterView>& toDraw, bool viewsKept);
};

}  // namespace pbr
