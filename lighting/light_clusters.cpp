#include "lighting/light_clusters.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <utility>

#include <glm/vec4.hpp>

#include "core/gl/debug_group.hpp"
#include "lighting/blended_programs.hpp"
#include "lighting/lighting_bindings.hpp"

namespace pbr {

namespace {

// Lights per invocation of the inline light pass (cluster_lights.comp): 4 took the million-light pass from
// 323-353 to 233-295 ms and the 65,536-light one from 46-50 to 34-46 ms (8: 232-334 ms), A B A B.
constexpr uint32_t kLightsPerInvocation = 4;

using LightPassBuild = LightClusters::LightPassBuild;

ShaderDefines lightPassDefines(bool spotLights, bool count, bool mark, bool stats, LightPassBuild build) {
  return concat(LightClusters::lightPassPermutation(spotLights, count, mark, stats, build), lightingBindingDefines());
}

// Lights per dispatch of the per-cluster light pass: each invocation loops over all of them (and a batch loop
// over a 64th as many), within llvmpipe's 65535 iterations.
constexpr uint32_t kPerClusterChunkLights = 32768;

ShaderDefines fillDefines(bool workgroupPerSlot) {
  return concat({{"WORKGROUP_PER_SLOT", workgroupPerSlot ? "1" : "0"}}, lightingBindingDefines());
}

// The most workgroups one dispatch dimension is sure to take (GL_MAX_COMPUTE_WORK_GROUP_COUNT's least maximum).
constexpr uint32_t kMaxGroups = 65535;

// Light-index entries per cluster holding a surface.
double listLength(const ClusterStatus& s) { return s.activeClusters ? double(s.demand) / s.activeClusters : 0.0; }

GLuint groupsFor(uint64_t items, uint32_t groupSize) { return static_cast<GLuint>((items + groupSize - 1) / groupSize); }

// Words of one slot's light mask over a window of lights (a bit per light), and of its summary (a bit per mask
// word): clusters.glsl's slotMaskWords and slotSummaryWords.
uint64_t maskWords(uint32_t lights) { return (uint64_t(lights) + 31) / 32; }
uint64_t summaryWords(uint32_t lights) { return (maskWords(lights) + 31) / 32; }
uint64_t slotBytes(uint32_t lights) { return (maskWords(lights) + summaryWords(lights)) * sizeof(uint32_t); }

// A storage buffer of `bytes` (at least one word, so that it can be bound), all zero.
std::unique_ptr<Buffer> zeroedBuffer(const char* label, uint64_t bytes) {
  auto buffer = std::make_unique<Buffer>(label, std::max<uint64_t>(bytes, 4), nullptr, 0);
  const uint32_t zero = 0;
  glClearNamedBufferData(buffer->id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
  return buffer;
}

// The occupancy pass's defines: with CASTER_PLANES planes, each point also finds its sides of them.
ShaderDefines casterPlaneDefines(size_t planes) {
  return {{"CASTER_PLANES", std::to_string(planes)}, {"MAX_CASTER_PLANES", std::to_string(kMaxCasterPlanes)}};
}

}  // namespace

float clusterSliceDepth(float nearPlane, float farPlane, int slice, int slices) {
  return nearPlane * std::pow(farPlane / nearPlane, static_cast<float>(slice) / static_cast<float>(slices));
}

LightClusters::LightClusters(ProgramCache& programs, const ClusterConfig& config)
    : config_(config),
      programs_(programs),
      occupancyProgram_(programs.compute("lighting/cluster_occupancy.comp",
                                         concat(casterPlaneDefines(0), lightingBindingDefines()))),
      activateProgram_(programs.compute("lighting/cluster_activate.comp", lightingBindingDefines())),
      tileBoxesProgram_(programs.compute("lighting/cluster_tile_boxes.comp", lightingBindingDefines())),
      compactProgram_(programs.compute("lighting/cluster_compact.comp", lightingBindingDefines())),
      scanProgram_(programs.compute("lighting/cluster_scan.comp", concat({{"ASSIGN_STATS", "0"}}, lightingBindingDefines()))),
      scanStatsProgram_(programs.compute("lighting/cluster_scan.comp", concat({{"ASSIGN_STATS", "1"}}, lightingBindingDefines()))),
      status_("clusters.status", sizeof(ClusterStatus), nullptr, 0) {
  setTileSize(config_.tileSize);
  GLint64 maxBlock = 0;
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &maxBlock);
  maxBlockBytes_ = static_cast<uint64_t>(std::max<GLint64>(maxBlock, 4));
  const uint64_t limitBytes = std::min<uint64_t>(config_.maxIndexBytes, maxBlockBytes_);
  maxCapacity_ = static_cast<uint32_t>(std::min<uint64_t>(limitBytes / 4, 0xFFFFFFFFull));
}

LightClusters::~LightClusters() {
  for (PendingStatus& p : pending_) {
    if (p.fence) glDeleteSync(p.fence);
  }
}

size_t LightClusters::bytes() const {
  size_t total = status_.size();
  for (const auto* b : {&headers_, &cursors_, &occupancy_, &boxes_, &clusterSlots_, &slotClusters_, &indices_,
                        &visible_, &slotMasks_[0], &slotMasks_[1], &bigLights_, &occupied_}) {
    total += *b ? (*b)->size() : 0;
  }
  return total;
}

void LightClusters::rebuildGrid(const FrameBlock& f) {
  const uint32_t w = static_cast<uint32_t>(f.viewport.x), h = static_cast<uint32_t>(f.viewport.y);
  const uint32_t tile = static_cast<uint32_t>(std::max(tileSize_, 1));
  builtTile_ = tileSize_;
  dims_ = glm::uvec3((w + tile - 1) / tile, (h + tile - 1) / tile, static_cast<uint32_t>(std::max(config_.slices, 1)));
  const uint32_t clusters = dims_.x * dims_.y * dims_.z;
  const float nearPlane = f.clip.x, farPlane = f.clip.y;
  const float scale = static_cast<float>(dims_.z) / std::log(farPlane / nearPlane);
  blockData_.dims = glm::uvec4(dims_, tile);
  // How far, in slices, a cluster's box may reach past its slice (the light pass widens each light's slice range
  // by it): the occupancy pass's 1e-3 of a slice, and the box's padding (occupiedBox: 1e-4 of its largest
  // coordinate, which inside the view is at most k times the depth of the slice's far end, k = max(1, 1/P00,
  // 1/P11) in perspective; in orthographic x and y reach 1/P00 and 1/P11 at any depth, at most k = max(1,
  // 1/(P00 near), 1/(P11 near)) times a depth past the near plane; plus 1e-6, at least the near plane's depth
  // away), doubled.
  const float depthScale = f.clip.w != 0.0f ? nearPlane : 1.0f;
  const float k = std::max(1.0f, std::max(1.0f / (f.projParams.x * depthScale), 1.0f / (f.projParams.y * depthScale)));
  const float margin = 2.0f * (1e-3f + scale * (1e-4f * k * std::exp(1.0f / scale) + 1e-6f / nearPlane));
  blockData_.slicing = glm::vec4(nearPlane, margin, scale, -scale * std::log(nearPlane));
  blockData_.counts = glm::uvec4(0, clusters, 0, 0);
  headers_ = std::make_unique<Buffer>("clusters.headers", clusters * sizeof(ClusterHeader), nullptr, 0);
  cursors_ = std::make_unique<Buffer>("clusters.cursors", clusters * sizeof(uint32_t), nullptr, 0);
  const uint64_t tiles = uint64_t(dims_.x) * dims_.y;
  const uint64_t occupancyBytes = (clusters + tiles) * kOccupancyWords * sizeof(uint32_t);
  occupancy_ = std::make_unique<Buffer>("clusters.occupancy", occupancyBytes, nullptr, 0);
  boxes_ = std::make_unique<Buffer>("clusters.boxes", (clusters + tiles) * kBoxBytes, nullptr, 0);
  // Per cluster its slot, then per tile its slices with one (clusters.glsl, tileSliceBase).
  clusterSlots_ = std::make_unique<Buffer>("clusters.slots", (clusters + tiles * ((dims_.z + 31) / 32)) * sizeof(uint32_t),
                                           nullptr, 0);
  slotClusters_.reset();
  slotCapacity_ = 0;
  expectedActive_ = 0;
  block_.update(blockData_);
  sizedFor_ = kNotSized;
  gridKey_ = f.viewport;
  gridKey2_ = f.projParams;
  // A first guess of 32 lights per cluster; the first frame measures the demand and grows the list to it.
  if (capacity_ < clusters * 32ull) ensureCapacity(clusters * 32ull);
}

void LightClusters::ensureCapacity(uint64_t entries) {
  if (entries > maxCapacity_) {
    if (!warnedLimit_) {
      std::fprintf(stderr,
                   "clusters: the light index list needs %llu entries (%.1f MiB), over its limit of %.1f MiB; "
                   "clusters that do not fit are shaded by brute force\n",
                   static_cast<unsigned long long>(entries), entries * 4.0 / (1 << 20), maxCapacity_ * 4.0 / (1 << 20));
      warnedLimit_ = true;
    }
    entries = maxCapacity_;
  }
  if (entries <= capacity_) return;
  while (glGetError() != GL_NO_ERROR) {
  }
  auto grown = std::make_unique<Buffer>("clusters.lightIndices", entries * sizeof(uint32_t), nullptr, 0);
  if (glGetError() == GL_OUT_OF_MEMORY) {
    if (!warnedLimit_) {
      std::fprintf(stderr, "clusters: out of GPU memory growing the light index list to %.1f MiB; clusters that do "
                           "not fit are shaded by brute force\n", entries * 4.0 / (1 << 20));
      warnedLimit_ = true;
    }
    return;
  }
  indices_ = std::move(grown);
  capacity_ = static_cast<uint32_t>(entries);
}

// Grown, never shrunk, and for at least one light, so that it can be bound.
void LightClusters::ensureLightBuffers(uint32_t lights) {
  const uint64_t bytes = 16 + uint64_t(std::max(lights, 1u)) * sizeof(uint32_t);
  if (!bigLights_ || bigLights_->size() < bytes) bigLights_ = std::make_unique<Buffer>("clusters.bigLights", bytes, nullptr, GL_DYNAMIC_STORAGE_BIT);
}

// A quarter of headroom over the clusters expected to hold a surface, as for the list. The slots are split over
// two buffers (shaders/lighting/slot_masks.glsl), each within the driver's largest storage block and half the
// budget. All lights in one window when their masks fit; else windows of a multiple of 1024 lights (the fill's
// chunks start on summary words), at least 1024, with fewer slots if even those do not fit. The masks are all
// zero between windows (cluster_fill.comp), whatever layout set them, so a buffer is only ever replaced by a
// larger one.
bool LightClusters::planMasks(uint32_t lights, uint32_t expectedActive) {
  const uint32_t clusters = blockData_.counts.y;
  const uint64_t perBuffer = std::min(config_.maxMaskBytes / 2, maxBlockBytes_);
  uint64_t capacity = std::min<uint64_t>(clusters, std::max<uint64_t>(64, expectedActive + expectedActive / 4ull));
  capacity = std::max<uint64_t>(capacity, slotCapacity_);
  lights = std::max(lights, 1u);
  uint64_t window = lights;
  const auto half = [](uint64_t slots) { return (slots + 1) / 2; };
  if (half(capacity) * slotBytes(lights) > perBuffer) {
    window = std::max<uint64_t>(1024, perBuffer / half(capacity) * 8 * 32 / 33 / 1024 * 1024);
    const uint64_t fit = std::max<uint64_t>(1, perBuffer / slotBytes(static_cast<uint32_t>(window)));
    if (2 * fit < expectedActive && !warnedMasks_) {
      std::fprintf(stderr, "clusters: light masks for %u clusters holding a surface exceed their budget of %.1f MiB; "
                           "the clusters past %llu are shaded by brute force\n",
                   expectedActive, 2.0 * perBuffer / (1 << 20), static_cast<unsigned long long>(2 * fit));
      warnedMasks_ = true;
    }
    capacity = std::min(capacity, 2 * fit);
  }
  const bool changed = capacity != slotCapacity_ || window != windowLights_;
  slotCapacity_ = static_cast<uint32_t>(capacity);
  windowLights_ = static_cast<uint32_t>(window);
  const uint64_t bufferBytes = half(capacity) * slotBytes(windowLights_);
  for (size_t i = 0; i < slotMasks_.size(); ++i) {
    if (!slotMasks_[i] || slotMasks_[i]->size() < bufferBytes) {
      slotMasks_[i] = zeroedBuffer(i == 0 ? "clusters.slotMasks" : "clusters.slotMasksHigh", bufferBytes);
    }
  }
  const uint64_t slotBytesTotal = (1 + capacity) * sizeof(uint32_t);
  if (!slotClusters_ || slotClusters_->size() < slotBytesTotal) {
    slotClusters_ = std::make_unique<Buffer>("clusters.slotClusters", slotBytesTotal, nullptr, 0);
  }
  blockData_.window = glm::uvec4(0, std::min(lights, windowLights_), maskWords(windowLights_), slotCapacity_);
  return changed;
}

void LightClusters::growFromPastDemand() {
  for (PendingStatus& p : pending_) {
    if (!p.fence) continue;
    if (glClientWaitSync(p.fence, 0, 0) == GL_TIMEOUT_EXPIRED) continue;
    glDeleteSync(p.fence);
    p.fence = nullptr;
    ClusterStatus s{};
    glGetNamedBufferSubData(p.buffer->id(), 0, sizeof s, &s);
    growTo(s.demand);
    expectedActive_ = std::max(expectedActive_, s.activeClusters);
    recentListLength_ = listLength(s);
  }
}

// A quarter of headroom, so that demand creeping up frame by frame does not regrow the list every frame.
void LightClusters::growTo(uint32_t demand) {
  if (demand > capacity_) ensureCapacity(static_cast<uint64_t>(demand) + demand / 4);
}

void LightClusters::assign(const FrameBlock& f, const UniformBuffer<FrameBlock>& frame, const LightBuffer& lights,
                           const Texture& depth, const BlendedSurfaces* blended, bool stats) {
  const bool newGrid = !headers_ || f.viewport != gridKey_ || f.projParams != gridKey2_ || builtTile_ != tileSize_;
  if (newGrid) rebuildGrid(f);
  growFromPastDemand();
  const uint32_t count = lights.count();
  const bool trialing = config_.lightPass == AssignShape::Automatic || config_.fill == AssignShape::Automatic;
  const auto mark = [this, trialing](AssignShapeTrials::Mark at) {
    if (trialing) trials_.mark(at);
  };
  if (trialing) trials_.beginFrame(count, expectedActive_, newGrid);
  ensureLightBuffers(count);
  planMasks(count, expectedActive_);
  const uint32_t clusters = blockData_.counts.y;
  blockData_.counts = glm::uvec4(count, clusters, capacity_, stats ? 1u : 0u);
  block_.update(blockData_);
  if (stats && (!visible_ || visible_->size() < count * 4ull)) visible_ = zeroedBuffer("clusters.visibleLights", count * 4ull);
  occupy(f, frame, depth, blended);
  lights.bind();
  headers_->bindBase(GL_SHADER_STORAGE_BUFFER, lighting_binding::kClusterSsbo.index);
  cursors_->bindBase(GL_SHADER_STORAGE_BUFFER, lighting_binding::kClusterCursorSsbo.index);
  occupancy_->bindBase(GL_SHADER_STORAGE_BUFFER, lighting_binding::kClusterOccupancySsbo.index);
  boxes_->bindBase(GL_SHADER_STORAGE_BUFFER, lighting_binding::kClusterBoxesSsbo.index);
  clusterSlots_->bindBase(GL_SHADER_STORAGE_BUFFER, lighting_binding::kClusterSlotsSsbo.index);
  bigLights_->bindBase(GL_SHADER_STORAGE_BUFFER, lighting_binding::kBigLightsSsbo.index);
  indices_->bindBase(GL_SHADER_STORAGE_BUFFER, lighting_binding::kLightIndexSsbo.index);
  status_.bindBase(GL_SHADER_STORAGE_BUFFER, lighting_binding::kClusterStatusSsbo.index);
  if (stats) visible_->bindBase(GL_SHADER_STORAGE_BUFFER, lighting_binding::kLightVisibleSsbo.index);
  activate();
  // Without a past frame of this grid and light count to size from, slots too few would shade the clusters
  // without one by brute force: such a frame waits for its count of active clusters instead.
  const bool sizing = count != sizedFor_;
  if (sizing) {
    const uint32_t active = readActiveCount();
    expectedActive_ = std::max(expectedActive_, active);
    if (active > slotCapacity_ && planMasks(count, expectedActive_)) {
      block_.update(blockData_);
      activate();
    }
  }
  const uint32_t windows = std::max(1u, (count + windowLights_ - 1) / windowLights_);
  if (trialing && trials_.trialFrame()) {
    // Compiled before the timestamps, so that no shape's time holds a compilation: the counting (and, in one
    // window, marking) pass and the windows' marking passes, in every shape tried.
    for (const bool windowPass : {false, windows > 1}) {
      for (const LightPassBuild build : {LightPassBuild::Inline, LightPassBuild::Queued, LightPassBuild::EveryLight,
                                         LightPassBuild::PerCluster}) {
        if (build == LightPassBuild::PerCluster && !trials_.triesClusterLightPass()) continue;
        programs_.compute("lighting/cluster_lights.comp",
                          lightPassDefines(lights.hasSpotLights(), !windowPass, windowPass || windows == 1,
                                           stats && !windowPass, build));
      }
    }
  }
  mark(AssignShapeTrials::LightPassBegin);
  dispatchLights(lights.hasSpotLights(), true, windows == 1, stats, 0, count);
  mark(AssignShapeTrials::LightPassEnd);
  dispatchScan(stats);
  // Likewise the list: a frame without a past one to size it from waits for its own demand.
  if (sizing) {
    sizedFor_ = count;
    const uint32_t before = capacity_;
    const ClusterStatus sized = readStatus();
    growTo(sized.demand);
    recentListLength_ = listLength(sized);
    if (capacity_ != before) {
      blockData_.counts.z = capacity_;
      block_.update(blockData_);
      indices_->bindBase(GL_SHADER_STORAGE_BUFFER, lighting_binding::kLightIndexSsbo.index);
      dispatchScan(stats);
    }
  }
  // With windows, the fill's time holds their marking light passes.
  mark(AssignShapeTrials::FillBegin);
  for (uint32_t w = 0; w < windows; ++w) {
    const uint32_t begin = w * windowLights_, end = std::min(count, begin + windowLights_);
    if (windows > 1) {
      setWindow(begin, end);
      dispatchLights(lights.hasSpotLights(), false, true, false, begin, end);
    }
    fillWindow(end - begin, w == 0, w + 1 == windows);
  }
  mark(AssignShapeTrials::FillEnd);

  PendingStatus& slot = pending_[pendingNext_];
  pendingNext_ = (pendingNext_ + 1) % pending_.size();
  if (slot.fence) glDeleteSync(slot.fence);
  if (!slot.buffer) {
    slot.buffer = std::make_unique<Buffer>("clusters.status.readback", sizeof(ClusterStatus), nullptr, 0);
  }
  glCopyNamedBufferSubData(status_.id(), slot.buffer->id(), 0, 0, sizeof(ClusterStatus));
  slot.fence = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
}

void LightClusters::occupy(const FrameBlock& f, const UniformBuffer<FrameBlock>& frame, const Texture& depth,
                           const BlendedSurfaces* blended) {
  const uint32_t empty = 0xFFFFFFFFu;  // a box no pixel grew (cluster_occupancy.comp)
  glClearNamedBufferData(occupancy_->id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &empty);
  frame.bind(kFrameUbo.index);
  block_.bind(lighting_binding::kClusterUbo.index);
  occupancy_->bindBase(GL_SHADER_STORAGE_BUFFER, lighting_binding::kClusterOccupancySsbo.index);
  glBindTextureUnit(lighting_binding::kDepthUnit.index, depth.id());
  const size_t planes = casterPlaneCount_;
  if (planes > 0) {
    if (!planeSides_) planeSides_ = std::make_unique<Buffer>("clusters.planeSides", 16, nullptr, 0);
    const uint32_t none = 0;
    glClearNamedBufferData(planeSides_->id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &none);
    casterPlanesBuffer_->bind(lighting_binding::kCasterPlanesUbo.index);
    planeSides_->bindBase(GL_SHADER_STORAGE_BUFFER, lighting_binding::kPlaneSidesSsbo.index);
  }
  const DebugGroup group("cluster occupancy");
  const Program& program =
      planes > 0 ? programs_.compute("lighting/cluster_occupancy.comp", concat(casterPlaneDefines(planes),
                                                                                  lightingBindingDefines()))
                 : occupancyProgram_;
  program.use();
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
  glDispatchCompute(groupsFor(static_cast<uint32_t>(f.viewport.x), 8),
                    groupsFor(static_cast<uint32_t>(f.viewport.y), 8), 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  if (!blended) return;
  const DebugGroup blendedGroup("cluster occupancy (blended surfaces)");
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  BlendedPrograms programs(programs_, "lighting/cluster_occupancy.frag", [planes](const std::vector<BindingPoint>& g) {
    return concat(casterPlaneDefines(planes), occupancyBindingDefines(g));
  });
  blended->draw(
      [&](int, const std::string& vertexShader, const ShaderDefines& material,
          const std::vector<BindingPoint>& bindings) -> const Program& {
        return programs.get(vertexShader, material, bindings);
      },
      BlendOrder::Any, 1, BlendedSet::All);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void LightClusters::measureOccupancy(const FrameBlock& f, const UniformBuffer<FrameBlock>& frame,
                                     const Texture& depth, const BlendedSurfaces* blended) {
  if (!headers_ || f.viewport != gridKey_ || f.projParams != gridKey2_ || builtTile_ != tileSize_) rebuildGrid(f);
  occupy(f, frame, depth, blended);
}

void LightClusters::setCasterPlanes(const std::vector<CasterPlane>& planes, const glm::mat4& toWorld) {
  const size_t count = std::min(planes.size(), kMaxCasterPlanes);
  casterPlaneCount_ = count;
  if (count == 0) return;
  // A plane p (p . x = 0 for x on it, x homogeneous) is p . toWorld y in view space: p times toWorld's columns;
  // the view is rigid, so the normal stays a unit vector.
  for (size_t i = 0; i < count; ++i) {
    const glm::vec4& p = planes[i].plane;
    casterPlanes_.planes[i] = glm::vec4(glm::dot(p, toWorld[0]), glm::dot(p, toWorld[1]), glm::dot(p, toWorld[2]),
                                        glm::dot(p, toWorld[3]));
    casterPlanes_.tolerances[i] = glm::vec4(planes[i].thickness, 0.0f, 0.0f, 0.0f);
  }
  if (!casterPlanesBuffer_) {
    casterPlanesBuffer_ = std::make_unique<UniformBuffer<CasterPlanesBlock>>("clusters.casterPlanes");
  }
  casterPlanesBuffer_->update(casterPlanes_);
}

uint32_t LightClusters::planeSides() const {
  if (casterPlaneCount_ == 0 || !planeSides_) return ~0u;
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  uint32_t sides = 0;
  glGetNamedBufferSubData(planeSides_->id(), 0, sizeof sides, &sides);
  return sides;
}

std::vector<ViewSpaceBox> LightClusters::occupiedBoxes() {
  const uint32_t clusters = blockData_.counts.y, tiles = dims_.x * dims_.y;
  const uint64_t bytes = 16 + uint64_t(clusters) * 32;
  if (!occupied_ || occupied_->size() < bytes) {
    occupied_ = std::make_unique<Buffer>("clusters.occupied", bytes, nullptr, 0);
  }
  const uint32_t zero = 0;
  glClearNamedBufferSubData(occupied_->id(), GL_R32UI, 0, sizeof zero, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
  block_.bind(lighting_binding::kClusterUbo.index);
  occupancy_->bindBase(GL_SHADER_STORAGE_BUFFER, lighting_binding::kClusterOccupancySsbo.index);
  occupied_->bindBase(GL_SHADER_STORAGE_BUFFER, lighting_binding::kOccupiedClustersSsbo.index);
  {
    const DebugGroup group("cluster compact");
    compactProgram_.use();
    glDispatchCompute(groupsFor(clusters, 64), 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  }
  uint32_t count = 0;
  glGetNamedBufferSubData(occupied_->id(), 0, sizeof count, &count);
  count = std::min(count, clusters);
  std::vector<glm::uvec4> entries(size_t(count) * 2);
  if (count > 0) {
    glGetNamedBufferSubData(occupied_->id(), 16, GLsizeiptr(entries.size() * sizeof(glm::uvec4)), entries.data());
  }
  // cluster_occupancy.comp's encoding: the minimum corner as ordered bits, the maximum as their complement
  // (clusters.glsl, orderedFloat).
  const auto decode = [](uint32_t u) {
    const uint32_t bits = (u & 0x80000000u) != 0u ? u & 0x7FFFFFFFu : ~u;
    float x;
    std::memcpy(&x, &bits, sizeof x);
    return x;
  };
  std::vector<std::pair<uint32_t, ViewSpaceBox>> boxes;
  boxes.reserve(count);
  for (uint32_t i = 0; i < count; ++i) {
    const glm::uvec4 &a = entries[2 * i], &b = entries[2 * i + 1];
    boxes.push_back({a.x, {{decode(a.y), decode(a.z), decode(a.w)}, {decode(~b.x), decode(~b.y), decode(~b.z)},
                           a.x % tiles}});
  }
  std::sort(boxes.begin(), boxes.end(), [](const auto& l, const auto& r) { return l.first < r.first; });
  std::vector<ViewSpaceBox> out;
  out.reserve(boxes.size());
  for (const auto& entry : boxes) out.push_back(entry.second);
  return out;
}

void LightClusters::activate() {
  const DebugGroup group("cluster activate");
  slotClusters_->bindBase(GL_SHADER_STORAGE_BUFFER, lighting_binding::kSlotClustersSsbo.index);
  slotMasks_[0]->bindBase(GL_SHADER_STORAGE_BUFFER, lighting_binding::kSlotMasksSsbo.index);
  slotMasks_[1]->bindBase(GL_SHADER_STORAGE_BUFFER, lighting_binding::kSlotMasksHighSsbo.index);
  const uint32_t zero = 0;
  glClearNamedBufferSubData(slotClusters_->id(), GL_R32UI, 0, sizeof zero, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
  // The tiles' slice bits, after the clusters' slots (which the pass writes whole).
  const GLintptr tileBits = GLintptr(blockData_.counts.y) * sizeof(uint32_t);
  glClearNamedBufferSubData(clusterSlots_->id(), GL_R32UI, tileBits, GLsizeiptr(clusterSlots_->size()) - tileBits,
                            GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
  activateProgram_.use();
  glDispatchCompute(groupsFor(blockData_.counts.y, 64), 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  tileBoxesProgram_.use();
  glDispatchCompute(groupsFor(uint64_t(dims_.x) * dims_.y, 64), 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

uint32_t LightClusters::readActiveCount() const {
  uint32_t active = 0;
  glGetNamedBufferSubData(slotClusters_->id(), 0, sizeof active, &active);
  return active;
}

void LightClusters::setWindow(uint32_t begin, uint32_t end) {
  blockData_.window.x = begin;
  blockData_.window.y = end;
  block_.update(blockData_);
}

ShaderDefines LightClusters::lightPassPermutation(bool spotLights, bool count, bool mark, bool stats,
                                                  LightPassBuild build) {
  const bool big = build == LightPassBuild::Queued || build == LightPassBuild::EveryLight;
  return {{"SPOT_LIGHTS", spotLights ? "1" : "0"}, {"LIGHT_COUNT", count ? "1" : "0"},
          {"LIGHT_MARK", mark ? "1" : "0"},        {"ASSIGN_STATS", stats ? "1" : "0"},
          {"BIG_LIGHTS", big ? "1" : "0"},
          {"EVERY_LIGHT", build == LightPassBuild::EveryLight ? "1" : "0"},
          {"PER_CLUSTER", build == LightPassBuild::PerCluster ? "1" : "0"},
          {"LIGHTS_PER_INVOCATION", std::to_string(kLightsPerInvocation)}};
}

void LightClusters::setTileSize(int pixels) { tileSize_ = std::max(pixels, 1); }

AssignShape LightClusters::lightPassShape() const {
  return config_.lightPass == AssignShape::Automatic ? trials_.lightPass() : config_.lightPass;
}

AssignShape LightClusters::fillShape() const {
  return config_.fill == AssignShape::Automatic ? trials_.fill() : config_.fill;
}

bool LightClusters::settled(uint32_t lights) const {
  const bool trialing = config_.lightPass == AssignShape::Automatic || config_.fill == AssignShape::Automatic;
  return headers_ && builtTile_ == tileSize_ && sizedFor_ == lights && (!trialing || trials_.decided());
}

std::string LightClusters::shapeSummary() const {
  std::string out = std::string("light pass ") + toString(lightPassShape()) + ", fill " + toString(fillShape());
  if (config_.lightPass != AssignShape::Automatic && config_.fill != AssignShape::Automatic) return out + " (forced)";
  if (!trials_.decided()) return out + " (timing the shapes: the invocation shape until all are measured)";
  const auto l = trials_.lightPassMs(), f = trials_.fillMs();
  char light[3][48];
  for (size_t i = 0; i < 3; ++i) std::snprintf(light[i], sizeof light[i], "%.3f", l[i]);
  if (!trials_.triesWorkgroupLightPass()) {
    std::snprintf(light[1], sizeof light[1], "not tried over %u lights", AssignShapeTrials::kMaxWorkgroupLightPass);
  }
  if (!trials_.triesClusterLightPass()) {
    std::snprintf(light[2], sizeof light[2], "not tried over %llu tests",
                  static_cast<unsigned long long>(AssignShapeTrials::kMaxPerClusterTests));
  }
  char measured[256];
  std::snprintf(measured, sizeof measured,
                " (timed here, invocation / workgroup / cluster: light pass %s / %s / %s ms, fill %.3f / %.3f ms)",
                light[0], light[1], light[2], f[0], f[1]);
  return out + measured;
}

void LightClusters::dispatchLights(bool spotLights, bool count, bool mark, bool stats, uint32_t begin, uint32_t end) {
  const DebugGroup group(count ? "cluster lights" : "cluster lights (window)");
  if (lightPassShape() == AssignShape::Cluster) {
    const Program& perCluster = programs_.compute(
        "lighting/cluster_lights.comp", lightPassDefines(spotLights, count, mark, stats, LightPassBuild::PerCluster));
    perCluster.use();
    for (uint32_t first = begin; first < end; first += std::min(end - first, kPerClusterChunkLights)) {
      const uint32_t last = first + std::min(end - first, kPerClusterChunkLights);
      for (uint64_t slot = 0; slot < slotCapacity_; slot += uint64_t(kMaxGroups) * 64) {
        glProgramUniform4ui(perCluster.id(), 0, first, last, uint32_t(slot), 0);
        glDispatchCompute(groupsFor(std::min<uint64_t>(slotCapacity_ - slot, uint64_t(kMaxGroups) * 64), 64), 1, 1);
      }
      glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    }
    return;
  }
  if (lightPassShape() == AssignShape::Workgroup) {
    const Program& perLight = programs_.compute(
        "lighting/cluster_lights.comp", lightPassDefines(spotLights, count, mark, stats, LightPassBuild::EveryLight));
    perLight.use();
    for (uint32_t first = begin; first < end; first += std::min(end - first, kMaxGroups)) {
      const uint32_t groups = std::min(end - first, kMaxGroups);
      glProgramUniform4ui(perLight.id(), 0, first, first + groups, 0, 0);
      glDispatchCompute(groups, 1, 1);
    }
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    return;
  }
  const uint32_t reset[4] = {0, 1, 1, 0};
  glNamedBufferSubData(bigLights_->id(), 0, sizeof reset, reset);
  const Program& inline_ = programs_.compute("lighting/cluster_lights.comp",
                                             lightPassDefines(spotLights, count, mark, stats, LightPassBuild::Inline));
  inline_.use();
  glProgramUniform4ui(inline_.id(), 0, begin, end, 0, 0);
  glDispatchCompute(groupsFor(end - begin, 64 * kLightsPerInvocation), 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
  programs_.compute("lighting/cluster_lights.comp",
                    lightPassDefines(spotLights, count, mark, stats, LightPassBuild::Queued)).use();
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, bigLights_->id());
  glDispatchComputeIndirect(0);
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void LightClusters::dispatchScan(bool stats) {
  const DebugGroup group("cluster scan");
  (stats ? scanStatsProgram_ : scanProgram_).use();
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

// In chunks of kAssignChunkLights, in ascending order, and at least one, so that a frame without lights still
// runs its (empty) fill. The fill leaves the window's masks zero.
void LightClusters::fillWindow(uint32_t windowLights, bool first, bool last) {
  const DebugGroup group("cluster fill");
  const bool perSlot = fillShape() != AssignShape::Invocation;  // a cluster's fill is its slot's workgroup
  const Program& program = programs_.compute("lighting/cluster_fill.comp", fillDefines(perSlot));
  program.use();
  const uint32_t chunks = std::max(1u, (windowLights + kAssignChunkLights - 1) / kAssignChunkLights);
  for (uint32_t c = 0; c < chunks; ++c) {
    const uint32_t begin = c * kAssignChunkLights, end = std::min(windowLights, begin + kAssignChunkLights);
    glProgramUniform4ui(program.id(), 0, begin, end, first && c == 0 ? 1u : 0u, last && c + 1 == chunks ? 1u : 0u);
    glDispatchCompute(perSlot ? std::max(1u, std::min(slotCapacity_, kMaxGroups)) : groupsFor(slotCapacity_, 64), 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  }
}

void LightClusters::bindForLighting() const {
  block_.bind(lighting_binding::kClusterUbo.index);
  headers_->bindBase(GL_SHADER_STORAGE_BUFFER, lighting_binding::kClusterSsbo.index);
  indices_->bindBase(GL_SHADER_STORAGE_BUFFER, lighting_binding::kLightIndexSsbo.index);
  status_.bindBase(GL_SHADER_STORAGE_BUFFER, lighting_binding::kClusterStatusSsbo.index);
}

std::vector<std::vector<uint32_t>> LightClusters::readLists() const {
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  const uint32_t clusters = blockData_.counts.y;
  std::vector<uint32_t> headers(clusters * 2ull);
  glGetNamedBufferSubData(headers_->id(), 0, static_cast<GLsizeiptr>(headers.size() * sizeof(uint32_t)), headers.data());
  std::vector<uint32_t> indices(capacity_);
  glGetNamedBufferSubData(indices_->id(), 0, static_cast<GLsizeiptr>(indices.size() * sizeof(uint32_t)), indices.data());
  std::vector<std::vector<uint32_t>> lists(clusters);
  for (uint32_t c = 0; c < clusters; ++c) {
    const uint32_t offset = headers[2 * c], count = headers[2 * c + 1];
    if (count <= capacity_ && offset <= capacity_ - count) {
      lists[c].assign(indices.begin() + offset, indices.begin() + offset + count);
    }
  }
  return lists;
}

bool LightClusters::growToDemand() {
  const uint32_t before = capacity_;
  const ClusterStatus status = readStatus();
  growTo(status.demand);
  const bool moreSlots = status.unslotted > 0 && status.activeClusters > expectedActive_;
  expectedActive_ = std::max(expectedActive_, status.activeClusters);
  return capacity_ > before || moreSlots;
}

ClusterStatus LightClusters::readStatus() const {
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  ClusterStatus s{};
  glGetNamedBufferSubData(status_.id(), 0, sizeof s, &s);
  return s;
}

}  // namespace pbr
