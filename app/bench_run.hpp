#pragma once
#include <chrono>
#include <functional>

#include "app/bench_sweep.hpp"
#include "core/shader_library.hpp"

namespace pbr {

using BenchClock = std::chrono::steady_clock;

// Called after every frame a configuration renders with the frames done and the most it will render.
using FrameProgress = std::function<void(int done, int total)>;

// Measures one configuration with a renderer of its own: warm-up frames, of which the first estimates the
// configuration's time and skips it when that exceeds settings.maxSeconds; timed frames with the camera fixed;
// then one untimed frame with GPU light statistics. `scene` already holds the configuration's lights.
BenchResult runBenchConfig(const ShaderLibrary& shaders, const Scene& scene, const BenchConfig& config,
                           const BenchSettings& settings, TimingMode timing, BenchClock::time_point sweepStart,
                           const FrameProgress& progress);

}  // namespace pbr
