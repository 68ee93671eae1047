#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <optional>

#include "core/gl/gl_objects.hpp"
#include "lighting/cluster_config.hpp"

namespace pbr {

// The automatic choice of each assignment pass's shape, by timing them on this machine: the same counts favour
// opposite shapes on a CPU rasterizer and on a GPU (docs/performance.md), and every shape gives the same lists, so
// the frames a trial takes are exact whichever runs. After the first frame of a light count on a grid (which sizes
// the lists and may compile programs), the next frames take the invocation, the workgroup and the cluster shape in
// turn (the cluster frame fills by invocation), GPU timestamps around each pass; once all are back, read without
// waiting, each pass keeps its fastest shape. Until then the invocation shape runs. The workgroup light pass is
// tried only up to kMaxWorkgroupLightPass lights: past them the invocation shape already gives a GPU over 16,384
// invocations (an H100 ran it 8x faster at a million lights), while a workgroup per light costs llvmpipe about 3
// ms per thousand lights. The cluster light pass is tried only where lights x clusters holding a surface is at
// most kMaxPerClusterTests, as it tests every pair.
class AssignShapeTrials {
 public:
  enum Mark { LightPassBegin, LightPassEnd, FillBegin, FillEnd };
  static constexpr uint32_t kMaxWorkgroupLightPass = 65536;
  static constexpr uint64_t kMaxPerClusterTests = uint64_t(1) << 22;

  // At the start of a frame's assignment: restarts the trials for a new light count or grid, and collects the
  // timestamps that have arrived. `activeClusters`: the clusters expected to hold a surface.
  void beginFrame(uint32_t lights, uint32_t activeClusters, bool gridChanged);
  AssignShape lightPass() const;
  AssignShape fill() const;
  // Whether this frame is a trial, and a timestamp of it.
  bool trialFrame() const;
  void mark(Mark at);

  bool decided() const { return lightPass_.has_value(); }
  // Fastest measured ms of each pass in each shape ([0] invocation, [1] workgroup, [2] cluster, the fill's
  // [2] unused); negative where not measured.
  std::array<double, 3> lightPassMs() const { return lightPassMs_; }
  std::array<double, 3> fillMs() const { return fillMs_; }
  // Whether this light count's trials time the workgroup and cluster light passes.
  bool triesWorkgroupLightPass() const { return lights_ <= kMaxWorkgroupLightPass; }
  bool triesClusterLightPass() const { return tryCluster_; }

 private:
  static constexpr int kFirstTrial = 1, kTrialFrames = 3;  // frames counted from a restart
  struct Trial {
    std::unique_ptr<std::array<Query, 4>> queries;
    bool issued = false, read = false;
  };
  int trialFrames() const { return tryCluster_ ? kTrialFrames : kTrialFrames - 1; }
  // The shapes trial `i` runs, as measured: the light pass's untried shapes run as the invocation one.
  AssignShape trialLightPass(int i) const;
  AssignShape trialFill(int i) const;
  void collect();

  uint32_t lights_ = ~0u;
  int frame_ = 0;  // trial frames begun since the last restart
  bool tryCluster_ = false;  // set on the first trial frame
  std::array<Trial, kTrialFrames> trials_;
  std::array<double, 3> lightPassMs_{-1.0, -1.0, -1.0}, fillMs_{-1.0, -1.0, -1.0};
  std::optional<AssignShape> lightPass_, fill_;
};

}  // namespace pbr
