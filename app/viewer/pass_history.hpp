#pragma once
#include <cstddef>
#include <deque>
#include <string>
#include <vector>

#include "core/io/frame_timing.hpp"

namespace pbr {

// The per-pass times of the last frames the profiler returned, for the overlay's stacked graph. Each pass name
// keeps the index it was first seen with, so that a pass keeps its colour while passes come and go with the
// culling or the debug view.
class PassHistory {
 public:
  static constexpr size_t kFrames = 300;  // five seconds at 60 Hz: long enough to see a change settle

  struct Frame {
    std::vector<std::pair<size_t, float>> passes;  // (index into names(), ms) in the order the frame ran them
    float totalMs() const;
  };

  void add(const FrameTiming& timing);  // drops the oldest frame beyond kFrames
  const std::deque<Frame>& frames() const { return frames_; }
  const std::vector<std::string>& names() const { return names_; }
  // The median time of pass `index` over the frames that ran it among the last `window`; 0 when none did.
  float medianMs(size_t index, size_t window) const;
  // Whether pass `index` ran in any of the last `window` frames.
  bool ranRecently(size_t index, size_t window) const;

 private:
  std::vector<std::string> names_;
  std::deque<Frame> frames_;
};

}  // namespace pbr
