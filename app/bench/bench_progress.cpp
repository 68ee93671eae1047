#include "app/bench/bench_progress.hpp"

#include <cstdio>
#include <string>
#include <utility>

namespace pbr {

BenchProgress::BenchProgress(std::vector<BenchConfig> configs, const BenchSettings& settings, bool terminal)
    : configs_(std::move(configs)), eta_(configs_, settings), terminal_(terminal), configStart_(BenchClock::now()) {}

void BenchProgress::started() { configStart_ = BenchClock::now(); }

void BenchProgress::frame(size_t index, int done, int total) const {
  if (!terminal_) return;
  constexpr size_t kWidth = 30;
  const size_t count = configs_.size();
  const double fraction = (static_cast<double>(index) + static_cast<double>(done) / total) / count;
  const size_t filled = static_cast<size_t>(fraction * kWidth);
  const std::string bar = std::string(filled, '#') + std::string(kWidth - filled, '-');
  const double elapsed = std::chrono::duration<double>(BenchClock::now() - configStart_).count();
  std::fprintf(stderr, "\r\033[K[%s] %3d%%  %zu/%zu %s  frame %d/%d  about %s left", bar.c_str(),
               static_cast<int>(fraction * 100.0), index + 1, count, configs_[index].label().c_str(), done, total,
               formatDuration(eta_.remainingSeconds(index, done, elapsed)).c_str());
  std::fflush(stderr);
}

void BenchProgress::finished(size_t index, const BenchResult& r) {
  eta_.finished(index, r);
  const size_t count = configs_.size();
  const std::string left =
      index + 1 < count ? ", about " + formatDuration(eta_.remainingAfter(index)) + " left" : "";
  if (terminal_) std::fprintf(stderr, "\r\033[K");
  if (r.skipped) {
    std::fprintf(stderr, "bench %zu/%zu %s: skipped, %s%s\n", index + 1, count, r.config.label().c_str(),
                 r.skipReason.c_str(), left.c_str());
  } else {
    std::fprintf(stderr, "bench %zu/%zu %s: frame %.2f ms (median of %zu), %.2f s%s\n", index + 1, count,
                 r.config.label().c_str(), r.frameTime.median, r.frames.size(), r.elapsedSeconds, left.c_str());
  }
  std::fflush(stderr);
}

}  // namespace pbr
