#include "app/bench/bench_progress.hpp"

#include <cstdio>
#include <string>

namespace pbr {

void BenchProgress::frame(size_t index, const BenchConfig& config, int done, int total) const {
  if (!terminal_) return;
  constexpr size_t kWidth = 30;
  const double fraction = (static_cast<double>(index) + static_cast<double>(done) / total) / configs_;
  const size_t filled = static_cast<size_t>(fraction * kWidth);
  const std::string bar = std::string(filled, '#') + std::string(kWidth - filled, '-');
  std::fprintf(stderr, "\r\033[K[%s] %3d%%  %zu/%zu %s  frame %d/%d", bar.c_str(), static_cast<int>(fraction * 100.0),
               index + 1, configs_, config.label().c_str(), done, total);
  std::fflush(stderr);
}

void BenchProgress::finished(size_t index, const BenchResult& r) const {
  if (terminal_) std::fprintf(stderr, "\r\033[K");
  if (r.skipped) {
    std::fprintf(stderr, "bench %zu/%zu %s: skipped, %s\n", index + 1, configs_, r.config.label().c_str(),
                 r.skipReason.c_str());
  } else {
    std::fprintf(stderr, "bench %zu/%zu %s: frame %.2f ms (median of %zu), %.2f s\n", index + 1, configs_,
                 r.config.label().c_str(), r.frameTime.median, r.frames.size(), r.elapsedSeconds);
  }
  std::fflush(stderr);
}

}  // namespace pbr
