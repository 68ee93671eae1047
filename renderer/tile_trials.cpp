#include "renderer/tile_trials.hpp"

#include <algorithm>
#include <cstdio>

namespace pbr {

int TileTrials::tile(const std::string& key, int base, bool settled, double listLength) {
  if (key != key_ || base != base_) {
    key_ = key;
    base_ = current_ = base;
    phase_ = Phase::Base;
    untried_.clear();
    for (Sample& s : samples_) s.issued = s.read = false;
  }
  timing_ = false;
  collect();
  switch (phase_) {
    case Phase::Base:
      if (!settled || !(listLength > 0.0)) break;
      if (listLength < kMinListLength || base_ / 2 < kMinTile) {
        char why[96];
        if (base_ / 2 < kMinTile) {
          std::snprintf(why, sizeof why, "the least side is %d pixels", kMinTile);
        } else {
          std::snprintf(why, sizeof why, "%.1f lights per occupied cluster, under %.0f", listLength, kMinListLength);
        }
        untried_ = why;
        phase_ = Phase::Decided;
        break;
      }
      if (issued(0) < kSamples) {
        timing_ = true;
        slot_ = issued(0);
        break;
      }
      // This frame builds the finer grid, untimed; it is timed once settled.
      phase_ = Phase::Fine;
      current_ = base_ / 2;
      break;
    case Phase::Fine:
      if (!settled) break;
      if (issued(kSamples) < kSamples) {
        timing_ = true;
        slot_ = kSamples + issued(kSamples);
        break;
      }
      phase_ = Phase::BaseAgain;
      current_ = base_;
      break;
    case Phase::BaseAgain:
      if (!settled) break;
      if (issued(2 * kSamples) < kSamples) {
        timing_ = true;
        slot_ = 2 * kSamples + issued(2 * kSamples);
        break;
      }
      phase_ = Phase::Collect;
      break;
    case Phase::Collect:
    case Phase::Decided:
      break;
  }
  return current_;
}

void TileTrials::mark(Mark at) {
  if (!timing_) return;
  Sample& s = samples_[static_cast<size_t>(slot_)];
  if (!s.queries) {
    s.queries = std::make_unique<std::array<Query, 2>>(
        std::array<Query, 2>{Query("tileTrials.begin"), Query("tileTrials.end")});
  }
  glQueryCounter((*s.queries)[at].id(), GL_TIMESTAMP);
  if (at == End) {
    s.issued = true;
    s.read = false;
  }
}

int TileTrials::issued(int first) const {
  int n = 0;
  for (int i = first; i < first + kSamples; ++i) n += samples_[static_cast<size_t>(i)].issued ? 1 : 0;
  return n;
}

double TileTrials::fastest(int side) const {
  double best = -1.0;
  for (int i = 0; i < int(samples_.size()); ++i) {
    const Sample& s = samples_[static_cast<size_t>(i)];
    if (sideOf(i) == side && s.read && (best < 0.0 || s.ms < best)) best = s.ms;
  }
  return best;
}

void TileTrials::collect() {
  bool all = true;
  for (Sample& s : samples_) {
    if (s.issued && !s.read && queryAvailable((*s.queries)[End])) {
      s.ms = spanMs(queryNs((*s.queries)[Begin]), queryNs((*s.queries)[End]));
      s.read = true;
    }
    all = all && s.read;
  }
  if (phase_ != Phase::Collect || !all) return;
  current_ = fastest(base_ / 2) < fastest(base_) ? base_ / 2 : base_;
  phase_ = Phase::Decided;
}

std::string TileTrials::summary() const {
  char text[200];
  if (phase_ != Phase::Decided) {
    std::snprintf(text, sizeof text, "%d-pixel tiles (timing %d- and %d-pixel tiles)", current_, base_, base_ / 2);
  } else if (!untried_.empty()) {
    std::snprintf(text, sizeof text, "%d-pixel tiles (%d-pixel ones not tried: %s)", current_, base_ / 2,
                  untried_.c_str());
  } else {
    std::snprintf(text, sizeof text, "%d-pixel tiles (timed here, cluster pass to lighting pass: %d px %.3f ms, %d px "
                  "%.3f ms)", current_, base_, fastest(base_), base_ / 2, fastest(base_ / 2));
  }
  return text;
}

}  // namespace pbr
