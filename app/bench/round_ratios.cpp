#include "app/bench/round_ratios.hpp"

#include <algorithm>
#include <string>

#include "app/bench/frame_stats.hpp"
#include "app/bench/text_table.hpp"
#include "core/scene/messages.hpp"

namespace pbr {

namespace {

std::string summary(const std::vector<double>& ratios) {
  if (ratios.empty()) return "-";
  const auto [lo, hi] = std::minmax_element(ratios.begin(), ratios.end());
  return fixedDecimals(median(ratios), 2) + "x (" + fixedDecimals(*lo, 2) + "-" + fixedDecimals(*hi, 2) + ")";
}

}  // namespace

std::vector<RoundRatios> roundRatios(const BenchReport& report) {
  std::vector<RoundRatios> all;
  if (report.provenance.get("frame_order").empty()) return all;
  for (const BenchResult& r : report.results) {
    if (r.skipped || r.frames.empty()) continue;
    const BenchResult* base = nullptr;
    for (const BenchResult& b : report.results) {
      if (b.config.culling != r.config.culling || b.config.model != r.config.model) continue;
      if (!base || b.config.lights < base->config.lights) base = &b;
    }
    if (base == &r || base->skipped || base->shard != r.shard || base->config.lights == r.config.lights) continue;
    RoundRatios ratios{&r, base, {}, {}};
    const bool clustered = r.config.culling == Culling::Clustered;
    for (size_t k = 0; k < std::min(r.frames.size(), base->frames.size()); ++k) {
      const FrameTiming &f = r.frames[k], &b = base->frames[k];
      if (b.gpuMs > 0.0) ratios.frame.push_back(f.gpuMs / b.gpuMs);
      if (clustered && b.pass("cluster") > 0.0) ratios.cluster.push_back(f.pass("cluster") / b.pass("cluster"));
    }
    all.push_back(std::move(ratios));
  }
  return all;
}

void printRoundRatios(std::ostream& out, const BenchReport& report) {
  const std::vector<RoundRatios> all = roundRatios(report);
  if (all.empty()) return;
  out << "\nper round, over the same culling and model at the fewest lights (frame k of each in round k): median "
         "(range)\n";
  std::vector<std::vector<std::string>> rows = {{"lights", "culling", "model", "vs", "frame", "cluster"}};
  for (const RoundRatios& r : all) {
    rows.push_back({std::to_string(r.result->config.lights), toString(r.result->config.culling),
                    toString(r.result->config.model), std::to_string(r.base->config.lights), summary(r.frame),
                    summary(r.cluster)});
  }
  const TextTable table(std::move(rows), {1, 2});
  for (size_t i = 0; i < table.rows(); ++i) out << table.line(i) << "\n";
}

}  // namespace pbr
