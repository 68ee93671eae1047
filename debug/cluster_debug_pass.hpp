#pragma once

#include "core/gl/program_cache.hpp"
#include "core/gl/uniform_buffer.hpp"
#include "core/scene/frame_block.hpp"
#include "debug/debug_channel.hpp"
#include "debug/debug_legend.hpp"
#include "lighting/light_clusters.hpp"

namespace pbr {

// Paints a debug view of the cluster grid (DebugChannel::Clusters or Slices) over the final RGBA8 frame, with a
// legend.
class ClusterDebugPass {
 public:
  explicit ClusterDebugPass(ProgramCache& programs) : programs_(programs) {}
  // Throws std::logic_error for a channel other than clusters and slices.
  void render(DebugChannel channel, const LightClusters& clusters, const Texture& depth,
              const UniformBuffer<FrameBlock>& frame, const UniformBuffer<LegendBlock>& legend, const Texture& ldr);

 private:
  ProgramCache& programs_;  // each view compiled on first use
};

}  // namespace pbr
