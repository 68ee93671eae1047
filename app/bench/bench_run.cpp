#include "app/bench/bench_run.hpp"

#include <sys/resource.h>

#include <cstdio>
#include <utility>

#include "app/provenance.hpp"

namespace pbr {

namespace {

double msSince(BenchClock::time_point t) {
  return std::chrono::duration<double, std::milli>(BenchClock::now() - t).count();
}

// User and system time of every thread of the process, llvmpipe's rasterizer threads included.
double processCpuMs() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const auto ms = [](const timeval& t) {
    return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_usec) * 1e-3;
  };
  return ms(usage.ru_utime) + ms(usage.ru_stime);
}

}  // namespace

TimedFrames timeFrames(Renderer& renderer, const FrameOptions& options, Profiler& profiler, int frames,
                       const std::function<void(int done)>& afterFrame) {
  profiler.takeResults(true);
  TimedFrames out;
  const BenchClock::time_point start = BenchClock::now();
  const double cpuStartMs = processCpuMs();
  for (int i = 0; i < frames; ++i) {
    renderer.renderFrame(options, profiler);
    if (afterFrame) afterFrame(i + 1);
  }
  out.frames = profiler.takeResults(true);
  out.processCpuShare = (processCpuMs() - cpuStartMs) / (msSince(start) * availableCpus());
  return out;
}

BenchRun::BenchRun(const ShaderLibrary& shaders, const Scene& scene, const BenchConfig& config, TimingMode timing)
    : renderer_(std::make_unique<Renderer>(shaders, scene, config.size.x, config.size.y, measuredGrid())),
      profiler_(std::make_unique<Profiler>(timing)) {
  result_.config = config;
  options_.model = config.model;
  options_.culling = config.culling;
  options_.shadows = config.shadows;
  options_.toneCurve = config.toneCurve;
  options_.exposure = scene.displayExposure();
}

BenchRun::~BenchRun() = default;

void BenchRun::frame(Profiler& profiler, bool rated) {
  const BenchClock::time_point start = BenchClock::now();
  const double cpuStartMs = processCpuMs();
  renderer_->renderFrame(options_, profiler);
  glFinish();  // with timer queries the frame may still be running
  const double wallMs = msSince(start);
  result_.elapsedSeconds += wallMs * 1e-3;
  if (rated) {
    ++framesAfterProbe_;
    secondsAfterProbe_ += wallMs * 1e-3;
  }
  if (timing_) {
    timedWallMs_ += wallMs;
    timedCpuMs_ += processCpuMs() - cpuStartMs;
  }
}

void BenchRun::probe(const BenchSettings& settings) {
  frame(*profiler_, false);
  probeSeconds_ = result_.elapsedSeconds;
  const int total = settings.warmup + settings.frames + 1;
  result_.estimatedSeconds = probeSeconds_ * total;
  if (result_.estimatedSeconds > settings.maxSeconds) {
    char reason[200];
    std::snprintf(reason, sizeof(reason),
                  "estimated %.1f s (first warm-up frame %.3f s x %d frames) exceeds --max-seconds %g",
                  result_.estimatedSeconds, probeSeconds_, total, settings.maxSeconds);
    result_.skipped = true;
    result_.skipReason = reason;
    renderer_.reset();
    return;
  }
  // Frames until the light lists fit, as the first frame sized them (Renderer::warmUp).
  const double before = result_.elapsedSeconds;
  const BenchClock::time_point start = BenchClock::now();
  renderer_->warmUp(options_, *profiler_, 0);
  glFinish();
  result_.elapsedSeconds = before + msSince(start) * 1e-3;
}

void BenchRun::warmUpFrame() { frame(*profiler_); }

void BenchRun::timedFrame(double sweepMs) {
  if (!timing_) {
    profiler_->takeResults(true);  // the warm-up frames
    result_.timelineStartMs = sweepMs;
    timing_ = true;
  }
  frame(*profiler_);
}

double BenchRun::frameSeconds() const {
  return framesAfterProbe_ > 0 ? secondsAfterProbe_ / framesAfterProbe_ : probeSeconds_;
}

BenchResult BenchRun::finish() {
  if (result_.skipped) return std::move(result_);
  result_.frames = profiler_->takeResults(true);
  result_.processCpuShare = timedWallMs_ > 0.0 ? timedCpuMs_ / (timedWallMs_ * availableCpus()) : 0.0;
  result_.memory = {renderer_->gbuffer().bytes(), renderer_->clusters().bytes(), renderer_->lights().bytes()};

  // The counters cost time: they come from one more frame, timed by nobody, so they never distort the timings.
  options_.stats = true;
  timing_ = false;
  Profiler untimed(profiler_->mode());
  frame(untimed, false);
  result_.stats = renderer_->lightStats();
  checkGlError("benchmarking " + result_.config.label());
  result_.summarize();
  renderer_.reset();
  return std::move(result_);
}

}  // namespace pbr
