#include "app/bench/bench_eta.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <utility>

namespace pbr {

namespace {

// `seconds` at `lights` scaled to `target` lights; a count of 0 says nothing of the scale.
double proportional(double seconds, int lights, int target) {
  return lights > 0 && target > 0 ? seconds * target / lights : seconds;
}

}  // namespace

SweepEta::SweepEta(std::vector<BenchConfig> configs, const BenchSettings& settings)
    : configs_(std::move(configs)),
      framesPerConfig_(settings.warmup + settings.frames + 1),
      maxSeconds_(settings.maxSeconds),
      frameSeconds_(configs_.size()) {}

void SweepEta::measured(size_t index, double frameSeconds) { frameSeconds_.at(index) = frameSeconds; }

double SweepEta::predictedSeconds(const BenchConfig& config, const std::vector<const Measured*>& measured) const {
  std::vector<const Measured*> same, any = measured;
  for (const Measured* m : measured) {
    if (m->config.culling == config.culling && m->config.model == config.model) same.push_back(m);
  }
  const auto byDistance = [&](const Measured* a, const Measured* b) {
    return std::abs(a->config.lights - config.lights) < std::abs(b->config.lights - config.lights);
  };
  std::stable_sort(same.begin(), same.end(), byDistance);
  std::stable_sort(any.begin(), any.end(), byDistance);
  double frame = 0.0;
  const auto other = std::find_if(same.begin(), same.end(),
                                  [&](const Measured* m) { return m->config.lights != same.front()->config.lights; });
  if (other != same.end()) {
    const Measured& a = *same.front();
    const Measured& b = **other;
    // Noise can tilt the line down, but more lights are never cheaper.
    const double slope = std::max((b.frameSeconds - a.frameSeconds) / (b.config.lights - a.config.lights), 0.0);
    frame = std::max(a.frameSeconds + slope * (config.lights - a.config.lights), 0.0);
  } else {
    const Measured& nearest = same.empty() ? *any.front() : *same.front();
    frame = proportional(nearest.frameSeconds, nearest.config.lights, config.lights);
  }
  return frame * framesPerConfig_ > maxSeconds_ ? frame : frame * framesPerConfig_;
}

double SweepEta::remainingSeconds(const std::vector<int>& framesLeft) const {
  std::vector<Measured> measured;
  for (size_t i = 0; i < configs_.size(); ++i) {
    if (frameSeconds_[i]) measured.push_back({configs_[i], *frameSeconds_[i]});
  }
  std::vector<const Measured*> pointers;
  for (const Measured& m : measured) pointers.push_back(&m);
  double seconds = 0.0;
  for (size_t i = 0; i < configs_.size() && i < framesLeft.size(); ++i) {
    if (frameSeconds_[i]) {
      seconds += *frameSeconds_[i] * framesLeft[i];
    } else if (framesLeft[i] > 0 && !pointers.empty()) {
      seconds += predictedSeconds(configs_[i], pointers);
    }
  }
  return seconds;
}

std::string formatDuration(double seconds) {
  const long s = std::lround(std::max(seconds, 0.0));
  char text[48];
  if (s < 60) {
    std::snprintf(text, sizeof(text), "%ld s", s);
  } else if (s < 3600) {
    std::snprintf(text, sizeof(text), "%ld min %02ld s", s / 60, s % 60);
  } else {
    std::snprintf(text, sizeof(text), "%ld h %02ld min", s / 3600, (s % 3600) / 60);
  }
  return text;
}

}  // namespace pbr
