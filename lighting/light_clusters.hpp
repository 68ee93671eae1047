#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
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
  // Exponential depth slices between the near and far planes. Thin slices raise culling efficiency, and only
  // slices holding a surface cost assignment work: on the stress scene 192 slices raise it from 0.40 (60 slices)
  // to 0.53 and shorten the frame (docs/performance.md).
  int slices = 192;
  // Most memory the light index list may take; past it, the clusters that do not fit are shaded by brute force.
  uint64_t maxIndexBytes = 512ull << 20;
};

// Depth-slice boundaries of the exponential slicing, shared by the GPU grid and its CPU documentation:
// slice k covers [near (far/near)^(k/S), near (far/near)^((k+1)/S)].
float clusterSliceDepth(float nearPlane, float farPlane, int slice, int slices);

// Lights per dispatch of the count and fill passes: their loops stay under llvmpipe's 65535 iterations per
// invocation (cluster_assign.comp) at any light count.
constexpr uint32_t kAssignChunkLights = 131072;

// Clustered light culling, per frame: the view-space boxes of the surfaces each cluster and each screen tile
// hold (from the depth buffer), each light in view space setting its bit in the masks of the tiles its projected
// sphere reaches and whose box it touches (cost: lights x tiles touched), a count pass testing each cluster that
// holds a surface against its tile's lights only, a prefix sum into list offsets and a fill pass writing one
// global, sorted light-index list, and a pass clearing the mask words set. The list is sized from the measured
// demand: the first frame of a grid and light count waits for its own; later frames read it a few frames late,
// so as never to wait, and one whose demand exceeds the list's capacity shades the clusters that do not fit by
// brute force (exact, just slower) while the list grows for the next frame.
class LightClusters {
 public:
  LightClusters(ProgramCache& programs, const ClusterConfig& config);
  ~LightClusters();
  LightClusters(const LightClusters&) = delete;
  LightClusters& operator=(const LightClusters&) = delete;

  // Culls `lights` into the clusters holding the surfaces of `depth` (the G-buffer's reversed-Z depth) for this
  // frame; `frameData` is what `frame` holds. Throws std::runtime_error when the tile masks for this many lights
  // would exceed the driver's largest storage buffer.
  void assign(const FrameBlock& frameData, const UniformBuffer<FrameBlock>& frame, const LightBuffer& lights,
              const Texture& depth, bool stats);
  // Binds the cluster block, headers, index list and status for the lighting pass and debug views.
  void bindForLighting() const;

  // This frame's status; waits for the GPU (use at the end of a run or in stats mode).
  ClusterStatus readStatus() const;
  // Grows the list at once to this frame's measured demand (waits for the GPU: for warm-up, not timed frames).
  // False when it did not grow: the demand fits, or the list is at its memory limit or out of memory.
  bool growToDemand();

  // Every cluster's light list of this frame (clusters are indexed (slice * tilesY + tileY) * tilesX + tileX);
  // a cluster that did not fit the index list, or holds no surface, reads as empty. Waits for the GPU: for tests
  // and tools.
  std::vector<std::vector<uint32_t>> readLists() const;

  glm::uvec3 dims() const { return dims_; }
  uint32_t capacity() const { return capacity_; }
  size_t bytes() const;

 private:
  void rebuildGrid(const FrameBlock& frameData);
  void growFromPastDemand();
  void growTo(uint32_t demand);
  void ensureCapacity(uint64_t entries);
  void ensureLightBuffers(uint32_t lights, bool spotLights);

  ClusterConfig config_;
  // `name`: the debug group the dispatches are in.
  void dispatchAssign(const char* name, const Program& program, uint32_t lights);

  ProgramCache& programs_;
  // The passes that read lights: cluster_lights.comp and cluster_assign.comp's count (without, with stats) and
  // fill, for frames of point lights and for frames with spot lights.
  struct AssignPrograms {
    const Program *lights, *count, *countStats, *fill;
  };
  static AssignPrograms assignPrograms(ProgramCache& programs, bool spotLights);
  const Program& occupancyProgram_;
  AssignPrograms pointPrograms_;
  std::optional<AssignPrograms> spotPrograms_;
  const Program &scanProgram_, &scanStatsProgram_, &clearProgram_;
  UniformBuffer<ClusterBlock> block_{"clusters.block"};
  ClusterBlock blockData_{};
  glm::uvec3 dims_{0};
  glm::vec4 gridKey_{0.0f};  // viewport + projection terms the bounds were built for
  glm::vec4 gridKey2_{0.0f};
  std::unique_ptr<Buffer> headers_, cursors_, occupancy_, indices_, visible_, viewLights_, tileMasks_, tileWords_;
  std::unique_ptr<Buffer> viewCones_;  // two vec4 per light (clusters.glsl), while frames have spot lights
  uint64_t maxBlockBytes_ = 0;  // GL_MAX_SHADER_STORAGE_BLOCK_SIZE
  Buffer status_;
  uint32_t capacity_ = 0;
  // The light count whose demand sized the list on this grid; another count sizes it within its first frame.
  static constexpr uint64_t kNotSized = ~0ull;
  uint64_t sizedFor_ = kNotSized;
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
