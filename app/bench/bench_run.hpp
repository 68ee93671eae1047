#pragma once
#include <chrono>
#include <functional>
#include <memory>

#include "app/bench/bench_sweep.hpp"
#include "core/gl/shader_library.hpp"
#include "renderer/renderer.hpp"

namespace pbr {

using BenchClock = std::chrono::steady_clock;

// Frames timed after warm-up, and the share of the available CPUs the process used meanwhile.
struct TimedFrames {
  std::vector<FrameTiming> frames;  // oldest first
  double processCpuShare = 0.0;     // see BenchResult::processCpuShare
};
// Discards what `profiler` still holds (warm-up frames), then renders and times `frames` frames; `afterFrame` is
// called with the number done after each.
TimedFrames timeFrames(Renderer& renderer, const FrameOptions& options, Profiler& profiler, int frames,
                       const std::function<void(int done)>& afterFrame = {});

// One configuration of a sweep with a renderer of its own, which lives until finish() so that the sweep can take
// the configurations' frames in turn: probe() renders the first warm-up frame, whose time x the frames the
// configuration renders estimates its time (it also pays for shader specialization and list sizing, so the
// estimate errs long) and skips it past settings.maxSeconds; warmUpFrame() and timedFrame() render one frame
// each; finish() renders one untimed frame with GPU light statistics and returns the result. Every call waits for
// its frame, so that one configuration's frame never overlaps another's.
class BenchRun {
 public:
  BenchRun(const ShaderLibrary& shaders, const Scene& scene, const BenchConfig& config, TimingMode timing);
  ~BenchRun();
  BenchRun(const BenchRun&) = delete;
  BenchRun& operator=(const BenchRun&) = delete;

  void probe(const BenchSettings& settings);
  bool skipped() const { return result_.skipped; }
  // The result so far: the configuration, its estimate or reason to skip, its time so far.
  const BenchResult& partial() const { return result_; }
  void warmUpFrame();
  // `sweepMs`: the time since the start of the sweep, where the first timed frame lies on the trace.
  void timedFrame(double sweepMs);
  BenchResult finish();

  // Seconds per frame: the first frame's, then the mean of those since.
  double frameSeconds() const;

 private:
  // Renders one frame on `profiler`, adding its wall time to the configuration's (and, when `rated`, to the
  // frames frameSeconds() averages: not the first, nor the statistics frame), and its CPU time once timed frames
  // have begun.
  void frame(Profiler& profiler, bool rated = true);

  std::unique_ptr<Renderer> renderer_;
  std::unique_ptr<Profiler> profiler_;
  FrameOptions options_;
  BenchResult result_;
  double probeSeconds_ = 0.0;
  int framesAfterProbe_ = 0;
  double secondsAfterProbe_ = 0.0;
  bool timing_ = false;  // timed frames have begun
  double timedWallMs_ = 0.0, timedCpuMs_ = 0.0;
};

}  // namespace pbr
