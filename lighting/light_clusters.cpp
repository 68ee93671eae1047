#include "lighting/light_clusters.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "core/debug_group.hpp"
#include "lighting/lighting_bindings.hpp"

namespace pbr {

namespace {

ShaderDefines assignDefines(bool spotLights, bool fill, bool stats) {
  return concat({{"SPOT_LIGHTS", spotLights ? "1" : "0"}, {"ASSIGN_FILL", fill ? "1" : "0"},
                 {"ASSIGN_STATS", stats ? "1" : "0"}},
                lightingBindingDefines());
}

GLuint groupsFor(uint64_t items, uint32_t groupSize) { return static_cast<GLuint>((items + groupSize - 1) / groupSize); }

// Words of one tile's light mask (a bit per light), and of its summary (a bit per mask word): clusters.glsl's
// clusterMaskWords and clusterSummaryWords.
uint64_t maskWords(uint32_t lights) { return (uint64_t(lights) + 31) / 32; }
uint64_t summaryWords(uint32_t lights) { return (maskWords(lights) + 31) / 32; }

// A storage buffer of `bytes` (at least one word, so that it can be bound), all zero.
std::unique_ptr<Buffer> zeroedBuffer(const char* label, uint64_t bytes) {
  auto buffer = std::make_unique<Buffer>(label, std::max<uint64_t>(bytes, 4), nullptr, 0);
  const uint32_t zero = 0;
  glClearNamedBufferData(buffer->id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
  return buffer;
}

std::string mebibytes(uint64_t bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f MiB", bytes / double(1 << 20));
  return text;
}

}  // namespace

LightClusters::AssignPrograms LightClusters::assignPrograms(ProgramCache& programs, bool spotLights) {
  const ShaderDefines lights = concat({{"SPOT_LIGHTS", spotLights ? "1" : "0"}}, lightingBindingDefines());
  return {&programs.compute("lighting/cluster_lights.comp", lights),
          &programs.compute("lighting/cluster_assign.comp", assignDefines(spotLights, false, false)),
          &programs.compute("lighting/cluster_assign.comp", assignDefines(spotLights, false, true)),
          &programs.compute("lighting/cluster_assign.comp", assignDefines(spotLights, true, false))};
}

float clusterSliceDepth(float nearPlane, float farPlane, int slice, int slices) {
  return nearPlane * std::pow(farPlane / nearPlane, static_cast<float>(slice) / static_cast<float>(slices));
}

LightClusters::LightClusters(ProgramCache& programs, const ClusterConfig& config)
    : config_(config),
      programs_(programs),
      occupancyProgram_(programs.compute("lighting/cluster_occupancy.comp", lightingBindingDefines())),
      pointPrograms_(assignPrograms(programs, false)),
      scanProgram_(programs.compute("lighting/cluster_scan.comp", concat({{"ASSIGN_STATS", "0"}}, lightingBindingDefines()))),
      scanStatsProgram_(programs.compute("lighting/cluster_scan.comp", concat({{"ASSIGN_STATS", "1"}}, lightingBindingDefines()))),
      clearProgram_(programs.compute("lighting/cluster_clear.comp", lightingBindingDefines())),
      status_("clusters.status", sizeof(ClusterStatus), nullptr, 0) {
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
  for (const auto* b : {&headers_, &cursors_, &occupancy_, &indices_, &visible_, &viewLights_, &viewCones_,
                        &tileMasks_, &tileWords_}) {
    total += *b ? (*b)->size() : 0;
  }
  return total;
}

void LightClusters::rebuildGrid(const FrameBlock& f) {
  const uint32_t w = static_cast<uint32_t>(f.viewport.x), h = static_cast<uint32_t>(f.viewport.y);
  const uint32_t tile = static_cast<uint32_t>(std::max(config_.tileSize, 1));
  dims_ = glm::uvec3((w + tile - 1) / tile, (h + tile - 1) / tile, static_cast<uint32_t>(std::max(config_.slices, 1)));
  const uint32_t clusters = dims_.x * dims_.y * dims_.z;
  const float nearPlane = f.clip.x, farPlane = f.clip.y;
  const float scale = static_cast<float>(dims_.z) / std::log(farPlane / nearPlane);
  blockData_.dims = glm::uvec4(dims_, tile);
  blockData_.slicing = glm::vec4(nearPlane, farPlane, scale, -scale * std::log(nearPlane));
  blockData_.counts = glm::uvec4(0, clusters, 0, 0);
  headers_ = std::make_unique<Buffer>("clusters.headers", clusters * sizeof(ClusterHeader), nullptr, 0);
  cursors_ = std::make_unique<Buffer>("clusters.cursors", clusters * sizeof(uint32_t), nullptr, 0);
  const uint64_t tiles = uint64_t(dims_.x) * dims_.y;
  const uint64_t occupancyBytes = (clusters + tiles) * kOccupancyWords * sizeof(uint32_t);
  occupancy_ = std::make_unique<Buffer>("clusters.occupancy", occupancyBytes, nullptr, 0);
  // The masks' layout depends on the tile count: new ones start empty.
  tileMasks_.reset();
  tileWords_.reset();
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

// Grown, never shrunk, and for at least one light, so that the buffers always exist to be bound. The masks are
// all zero between frames (cluster_clear.comp), whatever light count set them.
void LightClusters::ensureLightBuffers(uint32_t lights, bool spotLights) {
  const uint64_t tiles = uint64_t(dims_.x) * dims_.y;
  lights = std::max(lights, 1u);
  const uint64_t viewBytes = uint64_t(lights) * sizeof(ClusterViewLight);
  const uint64_t maskBytes = tiles * maskWords(lights) * sizeof(uint32_t);
  const uint64_t summaryBytes = tiles * summaryWords(lights) * sizeof(uint32_t);
  if (maskBytes > maxBlockBytes_) {
    throw std::runtime_error(std::to_string(lights) + " lights over " + std::to_string(tiles) + " screen tiles need " +
                             mebibytes(maskBytes) + " of tile masks, more than the OpenGL driver's largest storage "
                             "buffer (" + mebibytes(maxBlockBytes_) + "): use fewer lights, a smaller frame or a "
                             "larger --tile");
  }
  if (!viewLights_ || viewLights_->size() < viewBytes) {
    viewLights_ = std::make_unique<Buffer>("clusters.viewLights", viewBytes, nullptr, 0);
  }
  if (spotLights && (!viewCones_ || viewCones_->size() < 2 * viewBytes)) {
    viewCones_ = std::make_unique<Buffer>("clusters.viewCones", 2 * viewBytes, nullptr, 0);
  }
  if (!tileMasks_ || tileMasks_->size() < maskBytes) tileMasks_ = zeroedBuffer("clusters.tileMasks", maskBytes);
  if (!tileWords_ || tileWords_->size() < summaryBytes) tileWords_ = zeroedBuffer("clusters.tileWords", summaryBytes);
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
  }
}

// A quarter of headroom, so that demand creeping up frame by frame does not regrow the list every frame.
void LightClusters::growTo(uint32_t demand) {
  if (demand > capacity_) ensureCapacity(static_cast<uint64_t>(demand) + demand / 4);
}

void LightClusters::assign(const FrameBlock& f, const UniformBuffer<FrameBlock>& frame, const LightBuffer& lights,
                           const Texture& depth, bool stats) {
  if (!headers_ || f.viewport != gridKey_ || f.projParams != gridKey2_) rebuildGrid(f);
  growFromPastDemand();
  ensureLightBuffers(lights.count(), lights.hasSpotLights());
  const uint32_t clusters = blockData_.counts.y;
  const uint64_t tiles = uint64_t(dims_.x) * dims_.y;
  blockData_.counts = glm::uvec4(lights.count(), clusters, capacity_, stats ? 1u : 0u);
  block_.update(blockData_);
  if (stats && (!visible_ || visible_->size() < lights.count() * 4ull)) {
    visible_ = zeroedBuffer("clusters.visibleLights", lights.count() * 4ull);
  }
  const uint32_t empty = 0xFFFFFFFFu;  // a box no pixel grew (cluster_occupancy.comp)
  glClearNamedBufferData(occupancy_->id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &empty);

  frame.bind(kFrameUbo.index);
  block_.bind(lighting_binding::kClusterUbo.index);
  lights.bind();
  headers_->bindBase(GL_SHADER_STORAGE_BUFFER, lighting_binding::kClusterSsbo.index);
  cursors_->bindBase(GL_SHADER_STORAGE_BUFFER, lighting_binding::kClusterCursorSsbo.index);
  occupancy_->bindBase(GL_SHADER_STORAGE_BUFFER, lighting_binding::kClusterOccupancySsbo.index);
  indices_->bindBase(GL_SHADER_STORAGE_BUFFER, lighting_binding::kLightIndexSsbo.index);
  status_.bindBase(GL_SHADER_STORAGE_BUFFER, lighting_binding::kClusterStatusSsbo.index);
  viewLights_->bindBase(GL_SHADER_STORAGE_BUFFER, lighting_binding::kClusterViewLightsSsbo.index);
  tileMasks_->bindBase(GL_SHADER_STORAGE_BUFFER, lighting_binding::kClusterTileMasksSsbo.index);
  tileWords_->bindBase(GL_SHADER_STORAGE_BUFFER, lighting_binding::kClusterTileWordsSsbo.index);
  if (stats) visible_->bindBase(GL_SHADER_STORAGE_BUFFER, lighting_binding::kLightVisibleSsbo.index);
  glBindTextureUnit(lighting_binding::kDepthUnit.index, depth.id());

  {
    const DebugGroup group("cluster occupancy");
    occupancyProgram_.use();
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    glDispatchCompute(groupsFor(static_cast<uint32_t>(f.viewport.x), 8),
                      groupsFor(static_cast<uint32_t>(f.viewport.y), 8), 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  }
  // Spot lights' cones take permutations of their own, compiled the first time a frame has them.
  if (lights.hasSpotLights() && !spotPrograms_) spotPrograms_ = assignPrograms(programs_, true);
  const AssignPrograms& pass = lights.hasSpotLights() ? *spotPrograms_ : pointPrograms_;
  if (lights.hasSpotLights()) viewCones_->bindBase(GL_SHADER_STORAGE_BUFFER, lighting_binding::kClusterViewConesSsbo.index);
  {
    const DebugGroup group("cluster lights");
    pass.lights->use();
    glDispatchCompute(groupsFor(lights.count(), 64), 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  }
  dispatchAssign("cluster count", *(stats ? pass.countStats : pass.count), lights.count());
  const Program& scan = stats ? scanStatsProgram_ : scanProgram_;
  {
    const DebugGroup group("cluster scan");
    scan.use();
    glDispatchCompute(1, 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  }
  // Without a past frame of this grid and light count to size the list from, a list too small would shade its
  // clusters by brute force: with a million lights, minutes. Such a frame waits for its own demand instead.
  if (lights.count() != sizedFor_) {
    sizedFor_ = lights.count();
    const uint32_t before = capacity_;
    growTo(readStatus().demand);
    if (capacity_ != before) {
      const DebugGroup group("cluster scan (list grown)");
      blockData_.counts.z = capacity_;
      block_.update(blockData_);
      indices_->bindBase(GL_SHADER_STORAGE_BUFFER, lighting_binding::kLightIndexSsbo.index);
      scan.use();
      glDispatchCompute(1, 1, 1);
      glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    }
  }
  dispatchAssign("cluster fill", *pass.fill, lights.count());
  {
    const DebugGroup group("cluster clear");
    clearProgram_.use();
    glDispatchCompute(groupsFor(tiles * summaryWords(lights.count()), 64), 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  }

  PendingStatus& slot = pending_[pendingNext_];
  pendingNext_ = (pendingNext_ + 1) % pending_.size();
  if (slot.fence) glDeleteSync(slot.fence);
  if (!slot.buffer) {
    slot.buffer = std::make_unique<Buffer>("clusters.status.readback", sizeof(ClusterStatus), nullptr, 0);
  }
  glCopyNamedBufferSubData(status_.id(), slot.buffer->id(), 0, 0, sizeof(ClusterStatus));
  slot.fence = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
}

// The count or fill pass over the lights in chunks of kAssignChunkLights, in ascending order; one workgroup per
// tile and 8 slices (cluster_assign.comp). At least one chunk, so that a frame without lights still writes its
// (empty) headers.
void LightClusters::dispatchAssign(const char* name, const Program& program, uint32_t lights) {
  const DebugGroup group(name);
  program.use();
  const uint32_t chunks = std::max(1u, (lights + kAssignChunkLights - 1) / kAssignChunkLights);
  for (uint32_t c = 0; c < chunks; ++c) {
    const uint32_t begin = c * kAssignChunkLights, end = std::min(lights, begin + kAssignChunkLights);
    glProgramUniform4ui(program.id(), 0, begin, end, c == 0 ? 1u : 0u, c + 1 == chunks ? 1u : 0u);
    glDispatchCompute(dims_.x * dims_.y, groupsFor(dims_.z, 8), 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
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
  growTo(readStatus().demand);
  return capacity_ > before;
}

ClusterStatus LightClusters::readStatus() const {
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  ClusterStatus s{};
  glGetNamedBufferSubData(status_.id(), 0, sizeof s, &s);
  return s;
}

}  // namespace pbr
