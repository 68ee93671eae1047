#include "app/viewer/pass_history.hpp"

#include <algorithm>

namespace pbr {

float PassHistory::Frame::totalMs() const {
  float total = 0.0f;
  for (const auto& pass : passes) total += pass.second;
  return total;
}

void PassHistory::add(const FrameTiming& timing) {
  Frame frame;
  for (const PassTiming& pass : timing.passes) {
    const auto known = std::find(names_.begin(), names_.end(), pass.name);
    const size_t index = static_cast<size_t>(known - names_.begin());
    if (known == names_.end()) names_.push_back(pass.name);
    frame.passes.emplace_back(index, static_cast<float>(pass.ms));
  }
  frames_.push_back(std::move(frame));
  while (frames_.size() > kFrames) frames_.pop_front();
}

float PassHistory::medianMs(size_t index, size_t window) const {
  std::vector<float> times;
  const size_t first = frames_.size() - std::min(window, frames_.size());
  for (size_t i = first; i < frames_.size(); ++i) {
    for (const auto& pass : frames_[i].passes) {
      if (pass.first == index) times.push_back(pass.second);
    }
  }
  if (times.empty()) return 0.0f;
  const auto middle = times.begin() + static_cast<std::ptrdiff_t>(times.size() / 2);
  std::nth_element(times.begin(), middle, times.end());
  return *middle;
}

bool PassHistory::ranRecently(size_t index, size_t window) const {
  const size_t first = frames_.size() - std::min(window, frames_.size());
  for (size_t i = first; i < frames_.size(); ++i) {
    for (const auto& pass : frames_[i].passes) {
      if (pass.first == index) return true;
    }
  }
  return false;
}

}  // namespace pbr
