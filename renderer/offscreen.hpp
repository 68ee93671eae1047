#pragma once
#include <vector>

#include <glm/vec2.hpp>

#include "renderer/renderer.hpp"

namespace pbr {

struct RenderedFrames {
  ImageRgbaF hdr;  // the last frame's radiance before exposure
  ImageRgba8 ldr;  // the last frame as displayed
  LightStats stats;
  std::vector<FrameTiming> timings;  // every frame, oldest first
};

// Renders `frames` frames of `scene` off screen and captures the last one. More than one frame lets the clustered
// path size its light-index list from measured demand before the captured frame.
RenderedFrames renderOffscreen(const ShaderLibrary& shaders, const Scene& scene, glm::ivec2 size,
                               const FrameOptions& options, int frames = 2, const RendererConfig& config = {},
                               TimingMode timing = TimingMode::Serializing);

}  // namespace pbr
