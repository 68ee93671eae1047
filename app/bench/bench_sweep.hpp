#pragma once
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "renderer/frame_options.hpp"
#include "core/io/frame_timing.hpp"

namespace pbr {

// What `pbr bench` was asked to measure: every combination of light count, culling mode and shading model.
struct BenchSettings {
  std::string scene = "stress";
  glm::ivec2 size{1280, 720};
  std::vector<int> lights{64, 256, 1024, 4096, 16384};
  std::vector<Culling> culling{Culling::None, Culling::Clustered, kCommandCulling};
  std::vector<ShadingModel> models{ShadingModel::Pbr, ShadingModel::BlinnPhong};
  int warmup = 5;  // the first warm-up frame also estimates the configuration's time
  int frames = 30;
  double maxSeconds = 60.0;
  bool constantDensity = false;
  std::optional<float> spotShare;  // --spot-share: the share of random lights that are spots (else the scene's)
  // --shadows, --shadow-filter, --shadow-atlas, --shadow-cache: every configuration's. A benchmark draws the maps
  // every frame unless asked, so that its shadow pass is what a moving scene's frames pay.
  ShadowSettings shadows = [] {
    ShadowSettings s;
    s.cache = false;
    return s;
  }();
  ToneCurve toneCurve = ToneCurve::AcesHill;  // --tonemap: every PBR configuration's
  std::string timing = "auto";  // as requested; the mode used is in the provenance
};

// With --constant-density, light radii are scaled by sqrt(L0 / N), L0 the sweep's smallest light count, which
// holds N r^2 constant. Lights lie in a layer much thinner than it is wide, so a cluster much smaller than the
// lights sees a constant number of them; a cluster of extent s sees about N (r + s)^2, so where clusters are as
// large as the lights or larger (distant depth slices) the count still rises with N: docs/performance-history.md
// measures by how much.
int densityReferenceLights(const BenchSettings& settings);
float densityRadiusScale(int lights, int referenceLights);

// One point of the sweep.
struct BenchConfig {
  std::string scene;
  glm::ivec2 size{0};
  int lights = 0;
  Culling culling = Culling::Clustered;
  ShadingModel model = ShadingModel::Pbr;
  float radiusScale = 1.0f;  // applied to every light's radius
  ShadowSettings shadows;
  ToneCurve toneCurve = ToneCurve::AcesHill;
  std::string label() const;  // "1024 lights, clustered, pbr"
};

// The sweep's configurations in the order it measures them and its reports list them: light counts as given,
// then culling modes, then shading models, innermost.
std::vector<BenchConfig> sweepConfigs(const BenchSettings& settings);

// Order statistics of one timed quantity over the timed frames, in ms. Percentiles interpolate linearly between
// the two nearest ranks (as numpy's default does).
struct TimeSummary {
  double median = 0.0, p10 = 0.0, p90 = 0.0, min = 0.0, max = 0.0;
};
TimeSummary summarizeTimes(std::vector<double> ms);

struct PassSummary {
  std::string name;
  TimeSummary ms;
};

// GPU memory the frame's resources hold, in bytes.
struct MemoryUse {
  size_t gbuffer = 0, clusters = 0, lights = 0;
  size_t total() const { return gbuffer + clusters + lights; }
};

struct BenchResult {
  BenchConfig config;
  bool skipped = false;
  std::string skipReason;
  double estimatedSeconds = 0.0;  // the first warm-up frame's time x every frame the configuration would render
  double elapsedSeconds = 0.0;
  std::vector<FrameTiming> frames;  // the timed frames, oldest first
  double timelineStartMs = 0.0;     // when the timed frames began, from the start of the sweep (trace layout)
  int shard = 0;                    // in a merged report, the shard that measured it (its own timeline); else 0
  std::vector<PassSummary> passes;  // per pass, in the order the passes ran
  TimeSummary frameTime;            // first pass start to last pass end, on the timing clock
  TimeSummary cpuTime;              // the whole frame on the CPU clock
  // CPU time the process used during the timed frames over wall time x available CPUs. With a CPU rasterizer a
  // run sharing its cores with other work shows here as a lower share than a quiet run of the same configuration.
  double processCpuShare = 0.0;
  LightStats stats;                 // from one extra frame with FrameOptions::stats after the timed frames
  MemoryUse memory;

  // Fills passes, frameTime and cpuTime from frames.
  void summarize();
  const PassSummary* pass(const std::string& name) const;  // null when the pass did not run
};

// The passes a report has columns for: the renderer's usual ones, then any other that ran, in order of first
// appearance; a report's schema does not change with which configurations were skipped.
std::vector<std::string> reportedPasses(const std::vector<BenchResult>& results);

}  // namespace pbr
