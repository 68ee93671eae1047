#include "app/bench/bench_progress.hpp"

#include <cstdio>
#include <numeric>
#include <utility>

namespace pbr {

BenchProgress::BenchProgress(std::vector<BenchConfig> configs, const BenchSettings& settings, bool terminal)
    : configs_(std::move(configs)),
      eta_(configs_, settings),
      terminal_(terminal),
      framesLeft_(configs_.size(), eta_.framesPerConfig()),
      framesTotal_(static_cast<int>(configs_.size()) * eta_.framesPerConfig()),
      lastLine_(BenchClock::now()) {}

std::string BenchProgress::left() const { return "about " + formatDuration(eta_.remainingSeconds(framesLeft_)) + " left"; }

void BenchProgress::redraw(size_t index) const {
  if (!terminal_) return;
  constexpr size_t kWidth = 30;
  const int leftFrames = std::accumulate(framesLeft_.begin(), framesLeft_.end(), 0);
  const double fraction = framesTotal_ > 0 ? 1.0 - static_cast<double>(leftFrames) / framesTotal_ : 1.0;
  const size_t filled = static_cast<size_t>(fraction * kWidth);
  const std::string bar = std::string(filled, '#') + std::string(kWidth - filled, '-');
  std::fprintf(stderr, "\r\033[K[%s] %3d%%  %s, %zu/%zu %s  %s", bar.c_str(), static_cast<int>(fraction * 100.0),
               stage_.c_str(), index + 1, configs_.size(), configs_[index].label().c_str(), left().c_str());
  std::fflush(stderr);
}

void BenchProgress::rendered(size_t index, double frameSeconds) {
  eta_.measured(index, frameSeconds);
  if (framesLeft_[index] > 0) --framesLeft_[index];
  redraw(index);
}

void BenchProgress::probed(size_t index, const BenchResult& r) {
  if (r.skipped) framesLeft_[index] = 0;
  if (terminal_) std::fprintf(stderr, "\r\033[K");
  const size_t count = configs_.size();
  if (r.skipped) {
    std::fprintf(stderr, "bench %zu/%zu %s: skipped, %s, %s\n", index + 1, count, r.config.label().c_str(),
                 r.skipReason.c_str(), left().c_str());
  } else {
    std::fprintf(stderr, "bench %zu/%zu %s: estimated %.1f s, %s\n", index + 1, count, r.config.label().c_str(),
                 r.estimatedSeconds, left().c_str());
  }
  std::fflush(stderr);
  lastLine_ = BenchClock::now();
}

void BenchProgress::round(const char* phase, int round, int rounds) {
  stage_ = std::string(phase) + " round " + std::to_string(round) + "/" + std::to_string(rounds);
  if (terminal_ || (round < rounds && BenchClock::now() - lastLine_ < std::chrono::seconds(30))) return;
  std::fprintf(stderr, "bench: %s, %s\n", stage_.c_str(), left().c_str());
  std::fflush(stderr);
  lastLine_ = BenchClock::now();
}

void BenchProgress::finished(size_t index, const BenchResult& r) const {
  if (r.skipped) return;
  if (terminal_) std::fprintf(stderr, "\r\033[K");
  std::fprintf(stderr, "bench %zu/%zu %s: frame %.2f ms (median of %zu), %.2f s\n", index + 1, configs_.size(),
               r.config.label().c_str(), r.frameTime.median, r.frames.size(), r.elapsedSeconds);
  std::fflush(stderr);
}

}  // namespace pbr
