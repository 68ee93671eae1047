#pragma once
#include <functional>
#include <memory>
#include <vector>

#include "core/gl/gl_objects.hpp"
#include "core/gl/shadow_maps.hpp"
#include "shadows/shadow_plan.hpp"

namespace pbr {

// Draws the scene's casters' depth into `framebuffer`, once per view: the renderer hands in the geometry pass's
// depth drawing, so that this pass knows no other.
// Draws the casters into the views' squares; returns the draw calls made.
using DrawShadowCasters = std::function<size_t(GLuint framebuffer, const std::vector<ShadowCasterView>& views)>;

// The frame's shadow maps: plans them (planShadows), renders the planned squares into one depth atlas and uploads
// what the lighting pass reads (ShadowMaps). The atlas is allocated on the first shadowed frame, at the size the
// inputs ask, and again only when that size changes: a scene that shadows nothing never allocates one.
class ShadowPass {
 public:
  ShadowPass();
  void render(const ShadowInputs& inputs, const DrawShadowCasters& drawCasters);
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
};

}  // namespace pbr
