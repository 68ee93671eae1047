#include "core/gl/profiler.hpp"

#include <algorithm>
#include <cstdint>
#include <stdexcept>

namespace pbr {

void Profiler::beginFrame() {
  current_ = Frame{};
  current_.timing.frame = frameCounter_++;
  if (!spareQueries_.empty()) {
    current_.queries = std::move(spareQueries_.back());
    spareQueries_.pop_back();
  }
  frameStart_ = Clock::now();
}

Query& Profiler::nextQuery() {
  if (current_.used == current_.queries.size()) current_.queries.emplace_back("profiler.timestamp");
  return current_.queries[current_.used++];
}

void Profiler::stamp() {
  if (mode_ == TimingMode::GpuQueries) {
    glQueryCounter(nextQuery().id(), GL_TIMESTAMP);
  } else {
    glFinish();
    current_.cpuStamps.push_back(std::chrono::duration<double, std::milli>(Clock::now() - epoch_).count());
  }
}

void Profiler::beginPass(const char* name) {
  // Stamps are paired in order, so a pass inside another would be timed wrongly.
  if (passOpen_) throw std::logic_error(std::string("profiler: pass '") + name + "' begins inside another pass");
  passOpen_ = true;
  current_.timing.passes.push_back({name, 0.0});
  stamp();
}

void Profiler::endPass() {
  if (!passOpen_) throw std::logic_error("profiler: endPass without beginPass");
  passOpen_ = false;
  stamp();
}

void Profiler::endFrame() {
  current_.timing.cpuMs = std::chrono::duration<double, std::milli>(Clock::now() - frameStart_).count();
  inFlight_.push_back(std::move(current_));
  current_ = Frame{};
  drain(false);
}

void Profiler::drain(bool wait) {
  while (!inFlight_.empty() && resolve(inFlight_.front(), wait)) {
    done_.push_back(std::move(inFlight_.front().timing));
    spareQueries_.push_back(std::move(inFlight_.front().queries));
    inFlight_.pop_front();
  }
}

bool Profiler::resolve(Frame& frame, bool wait) {
  // Stamps relative to the frame's first one: GPU timestamps are nanoseconds from an arbitrary epoch, too large
  // for a double to keep sub-microsecond differences once converted.
  std::vector<double> stamps;
  double origin = 0.0;
  if (mode_ == TimingMode::Serializing) {
    origin = frame.cpuStamps.empty() ? 0.0 : frame.cpuStamps.front();
    for (double ms : frame.cpuStamps) stamps.push_back(ms - origin);
  } else {
    if (frame.used > 0 && !wait) {
      GLint available = GL_FALSE;
      glGetQueryObjectiv(frame.queries[frame.used - 1].id(), GL_QUERY_RESULT_AVAILABLE, &available);
      if (!available) return false;
    }
    GLuint64 first = 0;
    for (size_t i = 0; i < frame.used; ++i) {
      GLuint64 ns = 0;
      glGetQueryObjectui64v(frame.queries[i].id(), GL_QUERY_RESULT, &ns);
      if (i == 0) first = ns;
      stamps.push_back(static_cast<double>(static_cast<int64_t>(ns - first)) * 1e-6);
    }
    origin = static_cast<double>(first) * 1e-6;
  }
  FrameTiming& t = frame.timing;
  t.startMs = origin;
  for (size_t p = 0; p < t.passes.size(); ++p) {
    const double ms = stamps[2 * p + 1] - stamps[2 * p];
    t.passes[p].ms = ms > 0.0 ? ms : 0.0;
    t.passes[p].startMs = std::max(stamps[2 * p], 0.0);
  }
  t.gpuMs = stamps.empty() ? 0.0 : std::max(stamps.back(), 0.0);
  return true;
}

std::vector<FrameTiming> Profiler::takeResults(bool wait) {
  drain(wait);
  std::vector<FrameTiming> out;
  out.swap(done_);
  return out;
}

}  // namespace pbr
