#pragma once
#include <chrono>
#include <deque>
#include <string>
#include <vector>

#include "core/gl/debug_group.hpp"
#include "core/gl/gl_objects.hpp"
#include "core/io/frame_timing.hpp"

namespace pbr {

// Times each frame's passes as its TimingMode says, into FrameTimings (core/io/frame_timing.hpp).
class Profiler {
 public:
  explicit Profiler(TimingMode mode) : mode_(mode), epoch_(Clock::now()) {}
  TimingMode mode() const { return mode_; }

  void beginFrame();
  // Passes run one after another: beginPass inside an open pass, or endPass without one, throws std::logic_error.
  void beginPass(const char* name);
  void endPass();
  void endFrame();

  // Frames whose results are in, oldest first. With wait = false it never blocks on an unfinished query.
  // Query objects are recycled from frames already read, and new ones are made while every earlier set is still
  // in flight: however many frames are queued, neither endFrame nor takeResults(false) waits for the GPU.
  std::vector<FrameTiming> takeResults(bool wait);
  size_t framesInFlight() const { return inFlight_.size(); }

 private:
  using Clock = std::chrono::steady_clock;
  struct Frame {
    FrameTiming timing;
    std::vector<Query> queries;  // begin/end timestamp per pass
    std::vector<double> cpuStamps;  // ms since epoch_
    size_t used = 0;
  };
  Query& nextQuery();
  void stamp();
  bool resolve(Frame& frame, bool wait);
  void drain(bool wait);

  TimingMode mode_;
  Clock::time_point epoch_;
  int frameCounter_ = 0;
  bool passOpen_ = false;
  Frame current_;
  Clock::time_point frameStart_;
  std::deque<Frame> inFlight_;
  std::vector<std::vector<Query>> spareQueries_;
  std::vector<FrameTiming> done_;
};

// One pass for the lifetime of the object: a debug group of the pass's name around it, so that every timed pass
// is a group of the same name in a capture, and, with a profiler, timed (the group encloses the pass's time
// stamps, its own calls stay outside the time). Without a profiler (untimed work) only the group.
class ScopedPass {
 public:
  ScopedPass(Profiler* profiler, const char* name) : group_(name), profiler_(profiler) {
    if (profiler_) profiler_->beginPass(name);
  }
  ScopedPass(Profiler& profiler, const char* name) : ScopedPass(&profiler, name) {}
  ~ScopedPass() {
    if (profiler_) profiler_->endPass();
  }
  ScopedPass(const ScopedPass&) = delete;
  ScopedPass& operator=(const ScopedPass&) = delete;

 private:
  DebugGroup group_;
  Profiler* profiler_;
};

}  // namespace pbr
