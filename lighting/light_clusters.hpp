#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/vec3.hpp>

#include "core/frame_block.hpp"
#include "core/program_cache.hpp"
#include "core/uniform_buffer.hpp"
#include "lighting/cluster_block.hpp"
#include "lighting/light_buffer.hpp"

namespace pbr {

struct ClusterConfig {
  int tileSize = 64;  // pixels per screen tile side
  // Exponential depth slices between the near and far planes. Thin slices raise culling efficiency; since the
  // cluster passes test only their tile's lights, 60 cost the stress scene 13 % of its frame (docs/performance.md).
  int slices = 60;
  // Most memory the light index list may take; past it, the clusters that do not fit are shaded by brute force.
  uint64_t maxIndexBytes = 512ull << 20;
};

// Depth-slice boundaries of the exponential slicing, shared by the GPU grid and its CPU documentation:
// slice k covers [near (far/near)^(k/S), near (far/near)^((k+1)/S)].
float clusterSliceDepth(float nearPlane, float farPlane, int slice, int slices);

// Clustered light culling: froxel bounds (rebuilt when the projection or resolution changes), then per frame
// the lights in view space, a bit mask per screen tile of the lights reaching its frustum column, a count pass
// testing each cluster against its tile's lights only, a prefix sum into list offsets and a fill pass writing
// one global, sorted light-index list. The list is sized from the measured demand: a frame whose demand exceeds
// the list's capacity shades the clusters that do not fit by brute force (exact, just slower) and the list
// grows for the next frame.
class LightClusters {
 public:
  LightClusters(ProgramCache& programs, const ClusterConfig& config);
  ~LightClusters();
  LightClusters(const LightClusters&) = delete;
  LightClusters& operator=(const LightClusters&) = delete;

  // Culls `lights` into clusters for this frame; `frameData` is what `frame` holds.
  void assign(const FrameBlock& frameData, const UniformBuffer<FrameBlock>& frame, const LightBuffer& lights,
              bool stats);
  // Binds the cluster block, headers, index list and status for the lighting pass and debug views.
  void bindForLighting() const;

  // This frame's status; waits for the GPU (use at the end of a run or in stats mode).
  ClusterStatus readStatus() const;
  // Grows the list at once to this frame's measured demand (waits for the GPU: for warm-up, not timed frames).
  // False when it did not grow: the demand fits, or the list is at its memory limit or out of memory.
  bool growToDemand();

  // Every cluster's light list of this frame (clusters are indexed (slice * tilesY + tileY) * tilesX + tileX);
  // a cluster that did not fit the index list reads as empty. Waits for the GPU: for tests and tools.
  std::vector<std::vector<uint32_t>> readLists() const;

  glm::uvec3 dims() const { return dims_; }
  uint32_t capacity() const { return capacity_; }
  size_t bytes() const;

 private:
  void rebuildGrid(const FrameBlock& frameData, const UniformBuffer<FrameBlock>& frame);
  void growFromPastDemand();
  void growTo(uint32_t demand);
  void ensureCapacity(uint64_t entries);
  void ensureLightBuffers(uint32_t lights);

  ClusterConfig config_;
  const Program &boundsProgram_, &viewLightsProgram_, &tilesProgram_, &countProgram_, &countStatsProgram_,
      &scanProgram_, &scanStatsProgram_, &fillProgram_;
  UniformBuffer<ClusterBlock> block_;
  ClusterBlock blockData_{};
  glm::uvec3 dims_{0};
  glm::vec4 gridKey_{0.0f};  // viewport + projection terms the bounds were built for
  glm::vec4 gridKey2_{0.0f};
  std::unique_ptr<Buffer> bounds_, headers_, indices_, visible_, viewLights_, tileMasks_;
  Buffer status_;
  uint32_t capacity_ = 0;
  uint32_t maxCapacity_ = 0;
  bool warnedLimit_ = false;

  // Status copies read a few frames later, so that sizing the list never waits for the GPU.
  struct PendingStatus {
    std::unique_ptr<Buffer> buffer;
    GLsync fence = nullptr;
  };
  std::array<PendingStatus, 3> pending_;
  size_t pendingNext_ = 0;
};

}  // namespace pbr
