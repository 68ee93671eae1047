#pragma once
#include <chrono>
#include <functional>

#include "app/bench/bench_sweep.hpp"
#include "core/shader_library.hpp"

namespace pbr {

using BenchClock = std::chrono::steady_clock;

// Called after every frame a configuration renders with the frames done and the most it will render.
using FrameProgress = std::function<void(int done, int total)>;

// Frames timed after warm-up, and the share of the available CPUs the process used meanwhile.
struct TimedFrames {
  std::vector<FrameTiming> frames;  // oldest first
  double processCpuShare = 0.0;     // see BenchResult::processCpuShare
};
// Discards what `profiler` still holds (warm-up frames), then renders and times `frames` frames; `afterFrame` is
// called with the number done after each.
TimedFrames timeFrames(Renderer& renderer, const FrameOptions& options, Profiler& profiler, int frames,
                       const std::function<void(int done)>& afterFrame = {});

// Measures one configuration with a renderer of its own: warm-up frames, of which the first estimates the
// configuration's time and skips it when that exceeds settings.maxSeconds; timed frames with the camera fixed;
// then one untimed frame with GPU light statistics. `scene` already holds the configuration's lights.
BenchResult runBenchConfig(const ShaderLibrary& shaders, const Scene& scene, const BenchConfig& config,
                           const BenchSettings& settings, TimingMode timing, BenchClock::time_point sweepStart,
                           const FrameProgress& progress);

}  // namespace pbr
