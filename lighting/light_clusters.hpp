#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "core/gl/blended_surfaces.hpp"
#include "core/gl/program_cache.hpp"
#include "core/gl/uniform_buffer.hpp"
#include "core/scene/bounds.hpp"
#include "core/scene/frame_block.hpp"
#include "lighting/assign_shape_trials.hpp"
#include "lighting/caster_planes_block.hpp"
#include "lighting/cluster_block.hpp"
#include "lighting/cluster_config.hpp"
#include "lighting/light_buffer.hpp"

namespace pbr {

// Depth-slice boundaries of the exponential slicing, shared by the GPU grid and its CPU documentation:
// slice k covers [near (far/near)^(k/S), near (far/near)^((k+1)/S)].
float clusterSliceDepth(float nearPlane, float farPlane, int slice, int slices);

// Lights per dispatch of the fill pass: its loops stay under llvmpipe's 65535 iterations per invocation
// (cluster_fill.comp) at any light count.
constexpr uint32_t kAssignChunkLights = 131072;

// Clustered light culling, per frame: the view-space boxes of the surfaces each cluster and each screen tile
// hold (from the depth buffer) and a slot for each cluster holding one; each light, in view space, testing the
// clusters of the tiles its projected sphere reaches and of the slices its depth spans, counting itself in those
// whose box it touches and setting its bit in their masks (cost: lights x clusters they can reach); a prefix sum
// into list offsets; and a fill pass writing one global light-index list, each cluster's part in light order from
// its mask, leaving the mask words it read zero. Masks over more lights than their memory budget holds are built
// and filled in windows of lights, after a light pass that only counts. The list is sized from the measured
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
  // frame; `frameData` is what `frame` holds. With `blended`, the clusters its surfaces reach in front of `depth`
  // are occupied too, so that the forward lighting of BLEND surfaces finds their lights listed.
  void assign(const FrameBlock& frameData, const UniformBuffer<FrameBlock>& frame, const LightBuffer& lights,
              const Texture& depth, const BlendedSurfaces* blended, bool stats);
  // The first step of assign alone, the occupancy of the clusters by the surfaces of `depth` (and `blended`): for a
  // frame shaded without the lists (brute force) that still asks where its surfaces are (shadow planning).
  void measureOccupancy(const FrameBlock& frameData, const UniformBuffer<FrameBlock>& frame, const Texture& depth,
                        const BlendedSurfaces* blended);
  // The boxes of the surface points each occupied cluster holds, as the last assign or measureOccupancy measured
  // them, with their screen tiles, in view space, in cluster order. Waits for the GPU: the occupied clusters are
  // compacted on it (cluster_compact.comp), and read back as their count, then 32 bytes each.
  std::vector<ViewSpaceBox> occupiedBoxes();
  // The planar casters' planes (world space) the next occupancy passes test each visible point against, `toWorld`
  // the camera's inverse view matrix; none (the default) tests nothing. At most kMaxCasterPlanes.
  void setCasterPlanes(const std::vector<CasterPlane>& planes, const glm::mat4& toWorld);
  // The sides of those planes the last occupancy found visible points on (receiversAbove/Below); every side where
  // it tested none. Waits for the GPU: read with occupiedBoxes.
  uint32_t planeSides() const;
  // Binds the cluster block, headers, index list and status for the lighting pass and debug views.
  void bindForLighting() const;

  // This frame's status; waits for the GPU (use at the end of a run or in stats mode).
  ClusterStatus readStatus() const;
  // Grows the list and the masks' slots at once to this frame's measured demand (waits for the GPU: for warm-up,
  // not timed frames). False when neither grew: the demand fits, or the list is at its memory limit or out of
  // memory.
  bool growToDemand();

  // Every cluster's light list of this frame (clusters are indexed (slice * tilesY + tileY) * tilesX + tileX), as
  // indices into the light buffer (LightBuffer::sceneIndex gives the scene's); a cluster that did not fit the
  // index list, or holds no surface, reads as empty. Waits for the GPU: for tests and tools.
  std::vector<std::vector<uint32_t>> readLists() const;

  // The light pass's builds (cluster_lights.comp): four lights an invocation, queueing the large ones; a workgroup
  // per queued light (BIG_LIGHTS); a workgroup per light of a range (BIG_LIGHTS, EVERY_LIGHT); an invocation per
  // cluster slot (PER_CLUSTER).
  enum class LightPassBuild { Inline, Queued, EveryLight, PerCluster };
  // The defines of the light pass for these choices, without the binding defines.
  static ShaderDefines lightPassPermutation(bool spotLights, bool count, bool mark, bool stats, LightPassBuild build);
  // The tile side of the next assign's grid; a change builds the grid again (and sizes its lists, and times its
  // assignment shapes). The configured side until set.
  void setTileSize(int pixels);
  int tileSize() const { return builtTile_; }  // the side of the grid last built
  int askedTileSize() const { return tileSize_; }  // the side the next grid is built with
  // The shapes the passes take this frame: as configured, or as the trials choose.
  AssignShape lightPassShape() const;
  AssignShape fillShape() const;
  // The shapes of this frame and why: "light pass workgroup, fill invocation (timed here, ...)".
  std::string shapeSummary() const;

  // Whether the next assign of `lights` lights runs as later ones will: its lists sized on this grid, no
  // assignment shape left to time.
  bool settled(uint32_t lights) const;
  // Light-index entries per cluster holding a surface, from the latest status read back without waiting (0 before
  // any): the list length culling auto scales its clustered prediction by.
  double recentListLength() const { return recentListLength_; }
  glm::uvec3 dims() const { return dims_; }
  uint32_t capacity() const { return capacity_; }
  // Lights per mask window: all of them unless the masks exceed their budget.
  uint32_t windowLights() const { return windowLights_; }
  size_t bytes() const;

 private:
  void rebuildGrid(const FrameBlock& frameData);
  void growFromPastDemand();
  void growTo(uint32_t demand);
  void ensureCapacity(uint64_t entries);
  void ensureLightBuffers(uint32_t lights);
  // Slot capacity and window from the active clusters expected, within the masks' budget; false when unchanged.
  bool planMasks(uint32_t lights, uint32_t expectedActive);
  void activate();
  // cluster_lights.comp over lights [begin, end): counting hits, marking masks or both; then the lights it
  // queued as too large for one invocation, through an indirect dispatch.
  void dispatchLights(bool spotLights, bool count, bool mark, bool stats, uint32_t begin, uint32_t end);
  void dispatchScan(bool stats);
  // The fill pass over the current window; `first`/`last`: whether it is the frame's first/last.
  void fillWindow(uint32_t windowLights, bool first, bool last);
  void setWindow(uint32_t begin, uint32_t end);
  uint32_t readActiveCount() const;
  // Clears the occupancy and runs its pass over `depth` (cluster_occupancy.comp), then over the fragments of
  // `blended` (cluster_occupancy.frag), binding the frame and the block.
  void occupy(const FrameBlock& frameData, const UniformBuffer<FrameBlock>& frame, const Texture& depth,
              const BlendedSurfaces* blended);

  ClusterConfig config_;
  ProgramCache& programs_;
  const Program &occupancyProgram_, &activateProgram_, &tileBoxesProgram_, &compactProgram_, &scanProgram_,
      &scanStatsProgram_;
  UniformBuffer<ClusterBlock> block_{"clusters.block"};
  ClusterBlock blockData_{};
  glm::uvec3 dims_{0};
  int tileSize_ = 0;   // the side asked for (setTileSize)
  int builtTile_ = 0;  // the side of the grid built
  glm::vec4 gridKey_{0.0f};  // viewport + projection terms the bounds were built for
  glm::vec4 gridKey2_{0.0f};
  std::unique_ptr<Buffer> headers_, cursors_, occupancy_, boxes_, clusterSlots_, slotClusters_, indices_, visible_;
  std::array<std::unique_ptr<Buffer>, 2> slotMasks_;  // shaders/lighting/slot_masks.glsl
  std::unique_ptr<Buffer> bigLights_;
  std::unique_ptr<Buffer> occupied_;  // cluster_compact.comp's list, made on the first occupiedBoxes of a grid
  CasterPlanesBlock casterPlanes_{};
  size_t casterPlaneCount_ = 0;  // 0: the occupancy programs without the plane test
  std::unique_ptr<UniformBuffer<CasterPlanesBlock>> casterPlanesBuffer_;  // made with the first planes
  std::unique_ptr<Buffer> planeSides_;
  uint64_t maxBlockBytes_ = 0;  // GL_MAX_SHADER_STORAGE_BLOCK_SIZE
  uint32_t slotCapacity_ = 0;   // clusters with masks (slots); more active ones are shaded by brute force
  uint32_t windowLights_ = 0;   // lights per mask window
  uint32_t expectedActive_ = 0; // the most clusters holding a surface seen on this grid
  Buffer status_;
  uint32_t capacity_ = 0;
  // The light count whose demand sized the list on this grid; another count sizes it within its first frame.
  static constexpr uint64_t kNotSized = ~0ull;
  uint64_t sizedFor_ = kNotSized;
  uint32_t maxCapacity_ = 0;
  bool warnedLimit_ = false;
  bool warnedMasks_ = false;
  AssignShapeTrials trials_;
  double recentListLength_ = 0.0;

  // Status copies read a few frames later, so that sizing the list never waits for the GPU.
  struct PendingStatus {
    std::unique_ptr<Buffer> buffer;
    GLsync fence = nullptr;
  };
  std::array<PendingStatus, 3> pending_;
  size_t pendingNext_ = 0;
};

}  // namespace pbr
