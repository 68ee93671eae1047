#pragma once
#include <array>
#include <memory>
#include <string>

#include "core/gl/gl_objects.hpp"

namespace pbr {

// The cluster grid's tile side, chosen on this machine by timing it (docs/performance.md, "The grid's tile size"): a
// finer grid shortens long lists where lights are small against a tile, at the cost of assigning four times the
// clusters, and where that pays differs between a GPU and llvmpipe. Once a light count's lists are settled at the
// configured side and hold at least kMinListLength entries per occupied cluster, two frames are timed at that side,
// two at half of it and two at the configured side again, each once its grid is settled (GPU timestamps from the
// cluster pass's start to the lighting pass's end), and the side of the fastest frame is kept: timing the
// configured side on both sides of the finer one keeps a GPU's clocks, which rise over its first frames, from
// favouring the side timed last. Shorter lists keep the configured side untried. Lists are exact at any side, so
// every frame, timed or not, equals brute force.
class TileTrials {
 public:
  static constexpr double kMinListLength = 64.0;
  static constexpr int kMinTile = 8;
  enum Mark { Begin, End };

  // This frame's tile side. `key` names what the times depend on (light count, model, shadows, frame size); `base`
  // is the configured side; `settled`: whether the clusters are sized and their shapes chosen at the side returned
  // last; `listLength`: light-index entries per occupied cluster, as last measured (0: unknown).
  int tile(const std::string& key, int base, bool settled, double listLength);
  // Whether this frame is timed (its passes mark it), and whether the side is chosen.
  bool timing() const { return timing_; }
  bool decided() const { return phase_ == Phase::Decided; }
  void mark(Mark at);
  // "32-pixel tiles (timed here, cluster pass to lighting pass: 64 px 4.33 ms, 32 px 3.46 ms)", or why the finer
  // grid was not tried, or what is still being timed.
  std::string summary() const;

 private:
  enum class Phase { Base, Fine, BaseAgain, Collect, Decided };
  static constexpr int kSamples = 2;  // timed frames per side
  struct Sample {
    std::unique_ptr<std::array<Query, 2>> queries;
    bool issued = false, read = false;
    double ms = -1.0;
  };
  int issued(int first) const;
  double fastest(int side) const;  // the fastest frame read at that side
  void collect();

  std::string key_;
  Phase phase_ = Phase::Base;
  int base_ = 0, current_ = 0;
  bool timing_ = false;
  int slot_ = 0;  // the sample this frame's marks go to
  std::array<Sample, 3 * kSamples> samples_;  // the configured side's, the finer side's, the configured side's
  int sideOf(int sample) const { return sample / kSamples == 1 ? base_ / 2 : base_; }
  std::string untried_;  // why the finer grid was not tried, once decided so
};

}  // namespace pbr
