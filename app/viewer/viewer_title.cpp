#include "app/viewer/viewer.hpp"

#include <GLFW/glfw3.h>

#include <cstdio>
#include <string>

#include "app/bench/frame_stats.hpp"

namespace pbr {

namespace {
constexpr double kTitleIntervalMs = 250.0;  // often enough to read as live, rarely enough to be legible
}

void Viewer::updateTitle() {
  const Clock::time_point now = Clock::now();
  if (framesRendered_ > 1 && std::chrono::duration<double, std::milli>(now - lastTitle_).count() < kTitleIntervalMs) {
    return;
  }
  lastTitle_ = now;
  char buffer[96];
  if (overlay_) {  // the overlay carries the rest
    std::snprintf(buffer, sizeof buffer, "pbr view | %s", options_.sceneName.c_str());
    std::string title = buffer;
    if (!warmFrameMs_.empty()) {
      std::snprintf(buffer, sizeof buffer, " | %.1f ms",
                    median(std::vector<double>(warmFrameMs_.begin(), warmFrameMs_.end())));
      title += buffer;
    }
    glfwSetWindowTitle(window_.window(), title.c_str());
    return;
  }
  std::string title = "pbr view | warming up |";
  if (!warmTimings_.empty() && !warmFrameMs_.empty()) {
    std::snprintf(buffer, sizeof buffer, "pbr view | %.1f ms (median of %zu warm) |",
                  median(std::vector<double>(warmFrameMs_.begin(), warmFrameMs_.end())), warmFrameMs_.size());
    title = buffer;
    for (const PassTiming& p : medianPassTimes(std::vector<FrameTiming>(warmTimings_.begin(), warmTimings_.end()))) {
      std::snprintf(buffer, sizeof buffer, " %s %.2f", p.name.c_str(), p.ms);
      title += buffer;
    }
  }
  const FrameOptions& f = options_.frame;
  std::snprintf(buffer, sizeof buffer, " ms (%s) | %zu lights | %s %s | %s | exposure %.2f%s",
                profiler_.mode() == TimingMode::GpuQueries ? "GPU" : "serialized", lightCount(), toString(f.model),
                toString(f.culling), viewName(view_), f.exposure, options_.paused ? " | paused" : "");
  title += buffer;
  if (view_ && needsClusterGrid(*view_) && f.culling != Culling::Clustered) title += " (needs clustered culling: C)";
  glfwSetWindowTitle(window_.window(), title.c_str());
}

}  // namespace pbr
