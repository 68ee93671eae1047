#include "app/accuracy/pair_cost_report.hpp"

#include "app/bench/bench_report.hpp"
#include "core/scene/json_text.hpp"

#include <cstdio>
#include <string>

#include <nlohmann/json.hpp>

namespace pbr {

namespace {

std::string terms(const AccuracyVariant& v) { return describeTerms(v.model(), v.shading()); }

// What a row measures on: the fixture, or the scene of --pair-scene.
std::string frameText(const PairCostSettings& s) {
  const std::string size = std::to_string(s.size.x) + "x" + std::to_string(s.size.y) + ", ";
  if (s.scene.empty()) return size + std::to_string(s.lights) + " lights reaching every pixel, brute force";
  return size + "scene " + s.scene + " (" + std::to_string(s.lights) +
         " lights where it places random ones), brute force and clustered, per evaluated pair";
}

// Whether the rows have transparent columns: the fixture's pane is timed, a scene's BLEND surfaces are not.
bool timesTransparency(const PairCostSettings& s) { return s.scene.empty(); }

// A transparent column's number, or "-" where the rows have none.
std::string transparentText(const PairCostSettings& s, double value) {
  return timesTransparency(s) ? fixedDecimals(value, 4) : "-";
}

}  // namespace

KeyValues pairCostCsvProvenance(const PairCostReport& report) {
  KeyValues entries = report.provenance.entries;
  const PairCostSettings& s = report.settings;
  entries.push_back({"pair_cost_frame", frameText(s)});
  entries.push_back({"rounds", std::to_string(s.rounds)});
  return entries;
}

void writePairCostCsv(std::ostream& out, const PairCostReport& report) {
  const PairCostSettings& s = report.settings;
  out << "variant,material,model,terms,hdr_format,gbuffer,width,height,lights,rounds,ns_per_pair_median,"
         "ns_per_pair_p10,"
         "ns_per_pair_p90,ns_per_pair_min,ns_per_pair_max,fixed_share,pairs_per_frame,transparent_ns_per_pair_median,"
         "transparent_ns_per_pair_p10,transparent_ns_per_pair_p90,transparent_fixed_share,scene,culling\n";
  for (size_t i = 0; i < report.costs.size(); ++i) {
    const AccuracyVariant& v = report.variants[i];
    const PairCost& c = report.costs[i];
    out << v.name << ',' << toString(c.material) << ',' << toString(v.model()) << ",\"" << terms(v) << "\","
        << toString(v.hdr()) << ',' << toString(v.gbuffer()) << ',' << s.size.x << ',' << s.size.y << ','
        << s.lights << ',' << s.rounds << ','
        << fixedDecimals(c.nsPerPair.median, 4) << ',' << fixedDecimals(c.nsPerPair.p10, 4) << ','
        << fixedDecimals(c.nsPerPair.p90, 4) << ',' << fixedDecimals(c.nsPerPair.min, 4) << ','
        << fixedDecimals(c.nsPerPair.max, 4) << ',' << fixedDecimals(c.fixedShare, 4) << ','
        << c.pairs << ',' << transparentText(s, c.transparentNsPerPair.median) << ','
        << transparentText(s, c.transparentNsPerPair.p10) << ',' << transparentText(s, c.transparentNsPerPair.p90)
        << ',' << transparentText(s, c.transparentFixedShare) << ',' << (s.scene.empty() ? "pair-cost" : s.scene)
        << ',' << toString(c.culling) << '\n';
  }
}

void writePairCostJson(std::ostream& out, const PairCostReport& report) {
  using Json = nlohmann::ordered_json;
  Json provenance = Json::object();
  for (const auto& [key, value] : report.provenance.entries) provenance[key] = value;
  const PairCostSettings& s = report.settings;
  Json variants = Json::array();
  for (size_t i = 0; i < report.costs.size(); ++i) {
    const AccuracyVariant& v = report.variants[i];
    const PairCost& c = report.costs[i];
    const Json transparent = timesTransparency(s) ? Json({{"median", c.transparentNsPerPair.median},
                                                   {"p10", c.transparentNsPerPair.p10},
                                                   {"p90", c.transparentNsPerPair.p90},
                                                   {"min", c.transparentNsPerPair.min},
                                                   {"max", c.transparentNsPerPair.max}})
                                           : Json(nullptr);
    variants.push_back({{"variant", v.name},
                        {"material", toString(c.material)},
                        {"culling", toString(c.culling)},
                        {"model", toString(v.model())},
                        {"terms", terms(v)},
                        {"hdr_format", toString(v.hdr())},
                        {"gbuffer", toString(v.gbuffer())},
                        {"ns_per_pair", {{"median", c.nsPerPair.median},
                                         {"p10", c.nsPerPair.p10},
                                         {"p90", c.nsPerPair.p90},
                                         {"min", c.nsPerPair.min},
                                         {"max", c.nsPerPair.max}}},
                        {"fixed_share", c.fixedShare},
                        {"pairs_per_frame", c.pairs},
                        {"transparent_ns_per_pair", transparent},
                        {"transparent_fixed_share", timesTransparency(s) ? Json(c.transparentFixedShare) : Json(nullptr)}});
  }
  const Json doc = {{"schema", "pbr-pair-cost/1"},
                    {"provenance", provenance},
                    {"settings", {{"width", s.size.x}, {"height", s.size.y}, {"lights", s.lights}, {"rounds", s.rounds},
                                  {"culling", s.scene.empty() ? "none" : "none,clustered"},
                                  {"scene", s.scene.empty() ? "pair-cost" : s.scene}}},
                    {"variants", variants}};
  out << jsonText(doc, 2) << "\n";
}

void printPairCostTable(std::ostream& out, const PairCostReport& report) {
  const PairCostSettings& s = report.settings;
  out << "cost per light-pixel pair: " << frameText(s)
      << (s.scene.empty() ? " (opaque: the lighting pass; transparent: the transparency pass on a BLEND pane over it)"
                          : " (the lighting pass)")
      << ", " << s.rounds << " rounds taken in turn, "
      << report.provenance.get("timing_mode") << "\n"
      << report.provenance.get("gl_renderer") << ": " << report.provenance.get("timing_note") << "\n";
  char line[160];
  std::snprintf(line, sizeof line, "%-16s %-10s %-10s %10s %17s %12s %16s %17s %12s\n", "variant", "material",
                "culling", "ns/pair", "p10-p90", "fixed share", "transparent ns", "p10-p90", "fixed share");
  out << line;
  for (size_t i = 0; i < report.costs.size(); ++i) {
    const PairCost& c = report.costs[i];
    const TimeSummary& t = c.transparentNsPerPair;
    std::snprintf(line, sizeof line, "%-16s %-10s %-10s %10.3f %8.3f-%-8.3f %11.1f%%", report.variants[i].name.c_str(),
                  toString(c.material), toString(c.culling), c.nsPerPair.median, c.nsPerPair.p10, c.nsPerPair.p90,
                  c.fixedShare * 100.0);
    out << line;
    if (timesTransparency(s)) {
      std::snprintf(line, sizeof line, " %16.3f %8.3f-%-8.3f %11.1f%%\n", t.median, t.p10, t.p90,
                    c.transparentFixedShare * 100.0);
    } else {
      std::snprintf(line, sizeof line, " %16s %17s %12s\n", "-", "-", "-");
    }
    out << line;
  }
}

}  // namespace pbr
