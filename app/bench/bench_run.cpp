#include "app/bench/bench_run.hpp"

#include <sys/resource.h>

#include <cstdio>
#include <utility>

#include "core/provenance.hpp"

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

BenchResult runBenchConfig(const ShaderLibrary& shaders, const Scene& scene, const BenchConfig& config,
                           const BenchSettings& settings, TimingMode timing, BenchClock::time_point sweepStart,
                           const FrameProgress& progress) {
  const BenchClock::time_point start = BenchClock::now();
  BenchResult r;
  r.config = config;
  Renderer renderer(shaders, scene, config.size.x, config.size.y);
  Profiler profiler(timing);
  FrameOptions options;
  options.model = config.model;
  options.culling = config.culling;
  options.exposure = scene.displayExposure();
  const int total = settings.warmup + settings.frames + 1;

  // The first frame also pays for shader specialization and sizes the cluster lists, so the estimate errs long.
  const BenchClock::time_point probeStart = BenchClock::now();
  renderer.renderFrame(options, profiler);
  glFinish();  // with timer queries the frame may still be running
  const double probeSeconds = msSince(probeStart) * 1e-3;
  r.estimatedSeconds = probeSeconds * total;
  progress(1, total);
  if (r.estimatedSeconds > settings.maxSeconds) {
    char reason[200];
    std::snprintf(reason, sizeof(reason),
                  "estimated %.1f s (first warm-up frame %.3f s x %d frames) exceeds --max-seconds %g",
                  r.estimatedSeconds, probeSeconds, total, settings.maxSeconds);
    r.skipped = true;
    r.skipReason = reason;
    r.elapsedSeconds = msSince(start) * 1e-3;
    return r;
  }
  renderer.warmUp(options, profiler, settings.warmup - 1);
  progress(settings.warmup, total);
  r.timelineStartMs = msSince(sweepStart);
  TimedFrames timed = timeFrames(renderer, options, profiler, settings.frames,
                                 [&](int done) { progress(settings.warmup + done, total); });
  r.frames = std::move(timed.frames);
  r.processCpuShare = timed.processCpuShare;
  r.memory = {renderer.gbuffer().bytes(), renderer.clusters().bytes(), renderer.lights().bytes()};

  // The counters cost time: they come from one more frame, timed by nobody, so they never distort the timings.
  options.stats = true;
  Profiler untimed(timing);
  renderer.renderFrame(options, untimed);
  r.stats = renderer.lightStats();
  progress(total, total);
  checkGlError("benchmarking " + config.label());
  r.summarize();
  r.elapsedSeconds = msSince(start) * 1e-3;
  return r;
}

}  // namespace pbr
