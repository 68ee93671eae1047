#pragma once
#include <string>

#include "core/frame_block.hpp"
#include "core/program_cache.hpp"
#include "core/uniform_buffer.hpp"
#include "lighting/light_clusters.hpp"

namespace pbr {

enum class ClusterDebugView { None, Clusters, Slices };
ClusterDebugView parseClusterDebugView(const std::string& name);  // "none" | "clusters" | "slices"

// Paints a debug view of the cluster grid over the final RGBA8 frame, with a legend.
class ClusterDebugPass {
 public:
  explicit ClusterDebugPass(ProgramCache& programs) : programs_(programs) {}
  void render(ClusterDebugView view, const LightClusters& clusters, const Texture& depth,
              const UniformBuffer<FrameBlock>& frame, const Texture& ldr);

 private:
  ProgramCache& programs_;  // each view compiled on first use
};

}  // namespace pbr
