#include "app/bench/frame_stats.hpp"

#include <algorithm>

namespace pbr {

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

std::vector<PassTiming> medianPassTimes(const std::vector<FrameTiming>& frames) {
  std::vector<std::string> names;
  for (const FrameTiming& f : frames) {
    for (const PassTiming& p : f.passes) {
      if (std::find(names.begin(), names.end(), p.name) == names.end()) names.push_back(p.name);
    }
  }
  std::vector<PassTiming> out;
  for (const std::string& name : names) {
    std::vector<double> values;
    for (const FrameTiming& f : frames) {
      const bool present = std::any_of(f.passes.begin(), f.passes.end(), [&](const PassTiming& p) { return p.name == name; });
      if (present) values.push_back(f.pass(name));
    }
    out.push_back({name, median(values)});
  }
  return out;
}

}  // namespace pbr
