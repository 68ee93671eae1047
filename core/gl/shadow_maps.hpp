#pragma once
#include "core/gl/gl.hpp"
#include "core/scene/shadow_settings.hpp"

namespace pbr {

// Shadow maps as shaders sample them (shaders/shadows/shadow_sample.glsl): one depth atlas with a comparison
// sampler, the views rendered into it, and per light the views it owns. The contract between the pass that renders
// the maps (shadows/) and the pass that reads them (lighting/), neither of which knows the other. Handles only: the
// maps belong to their maker.
struct ShadowMaps {
  GLuint atlas = 0, atlasSampler = 0;  // DEPTH_COMPONENT32F, reversed Z (1 nearest the light), compare GEQUAL
  GLuint views = 0;                    // storage buffer: GpuShadowHeader then the cascades' GpuCascadeView[]
  GLuint lightViews = 0;               // storage buffer: per light-buffer index, its entry (lightShadowEntry)
  GLuint squares = 0;                  // storage buffer: per view, its square packed (packShadowSquare)
};

// Binds the maps where shadow_sample.glsl reads them (core/scene/shadow_settings.hpp).
void bindShadowMaps(const ShadowMaps& maps);

}  // namespace pbr
