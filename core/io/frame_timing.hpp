#pragma once
#include <string>
#include <vector>

// How a run's passes are timed and what a frame's timings hold, with no GL: the records that reports carry. The
// profiler that takes them is core/gl/profiler.hpp.
namespace pbr {

// GpuQueries: GL_TIMESTAMP queries around each pass, read back frames later without stalling.
// Serializing: glFinish before and after each pass and a monotonic CPU clock. Software rasterizers (llvmpipe)
// report near-zero timer-query times for draw calls, so passes there are timed this way, and say so.
enum class TimingMode { GpuQueries, Serializing };

// `requested` is "auto", "gpu" or "serial"; auto serializes on software rasterizers.
TimingMode chooseTimingMode(const std::string& requested, const std::string& glRenderer);
const char* describe(TimingMode mode);

struct PassTiming {
  std::string name;
  double ms = 0.0;
  double startMs = 0.0;  // from the start of the frame's first pass
};

struct FrameTiming {
  int frame = 0;
  std::vector<PassTiming> passes;
  double gpuMs = 0.0;  // first pass start to last pass end
  double cpuMs = 0.0;  // beginFrame to endFrame on the CPU clock
  // Start of the first pass on the timing clock (GPU timestamps, or the CPU clock since the profiler was made):
  // only differences between frames of one profiler mean anything, e.g. to lay frames out on a timeline.
  double startMs = 0.0;
  double pass(const std::string& name) const;
};

}  // namespace pbr
