#include "app/bench/bench_sweep.hpp"

#include <algorithm>
#include <cmath>

#include "app/bench/frame_stats.hpp"

namespace pbr {

namespace {

// Linear interpolation between the closest ranks of sorted values, q in [0, 1].
double percentile(const std::vector<double>& sorted, double q) {
  const double rank = q * static_cast<double>(sorted.size() - 1);
  const size_t lo = static_cast<size_t>(std::floor(rank));
  const size_t hi = std::min(lo + 1, sorted.size() - 1);
  return sorted[lo] + (sorted[hi] - sorted[lo]) * (rank - static_cast<double>(lo));
}

}  // namespace

int densityReferenceLights(const BenchSettings& settings) {
  return settings.lights.empty() ? 0 : *std::min_element(settings.lights.begin(), settings.lights.end());
}

float densityRadiusScale(int lights, int referenceLights) {
  return lights > 0 && referenceLights > 0
             ? std::sqrt(static_cast<float>(referenceLights) / static_cast<float>(lights))
             : 1.0f;
}

std::string BenchConfig::label() const {
  return std::to_string(lights) + " lights, " + toString(culling) + ", " + toString(model);
}

std::vector<BenchConfig> sweepConfigs(const BenchSettings& settings) {
  std::vector<BenchConfig> configs;
  for (int lights : settings.lights) {
    const float scale =
        settings.constantDensity ? densityRadiusScale(lights, densityReferenceLights(settings)) : 1.0f;
    for (Culling culling : settings.culling) {
      for (ShadingModel model : settings.models) {
        configs.push_back(
            {settings.scene, settings.size, lights, culling, model, scale, settings.shadows, settings.toneCurve});
      }
    }
  }
  return configs;
}

TimeSummary summarizeTimes(std::vector<double> ms) {
  if (ms.empty()) return {};
  std::sort(ms.begin(), ms.end());
  return {median(ms), percentile(ms, 0.1), percentile(ms, 0.9), ms.front(), ms.back()};
}

void BenchResult::summarize() {
  passes.clear();
  for (const FrameTiming& f : frames) {
    for (const PassTiming& p : f.passes) {
      if (!pass(p.name)) passes.push_back({p.name, {}});
    }
  }
  for (PassSummary& summary : passes) {
    std::vector<double> ms;
    for (const FrameTiming& f : frames) {
      if (std::any_of(f.passes.begin(), f.passes.end(), [&](const PassTiming& p) { return p.name == summary.name; })) {
        ms.push_back(f.pass(summary.name));
      }
    }
    summary.ms = summarizeTimes(ms);
  }
  std::vector<double> gpu, cpu;
  for (const FrameTiming& f : frames) {
    gpu.push_back(f.gpuMs);
    cpu.push_back(f.cpuMs);
  }
  frameTime = summarizeTimes(gpu);
  cpuTime = summarizeTimes(cpu);
}

const PassSummary* BenchResult::pass(const std::string& name) const {
  auto it = std::find_if(passes.begin(), passes.end(), [&](const PassSummary& p) { return p.name == name; });
  return it == passes.end() ? nullptr : &*it;
}

std::vector<std::string> reportedPasses(const std::vector<BenchResult>& results) {
  std::vector<std::string> names{"gbuffer", "cluster", "lighting", "post"};
  for (const BenchResult& r : results) {
    for (const PassSummary& p : r.passes) {
      if (std::find(names.begin(), names.end(), p.name) == names.end()) names.push_back(p.name);
    }
  }
  return names;
}

}  // namespace pbr
