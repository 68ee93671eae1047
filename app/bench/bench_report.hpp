#pragma once
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "app/bench/bench_shard.hpp"
#include "app/bench/bench_sweep.hpp"
#include "app/bench/csv_provenance.hpp"
#include "core/scene/messages.hpp"
#include "app/provenance.hpp"

namespace pbr {

// Everything `pbr bench` measured, and under which circumstances.
struct BenchReport {
  Provenance provenance;
  BenchSettings settings;
  std::vector<BenchResult> results;  // in sweep order, skipped configurations included
  std::optional<BenchShard> shard;   // set when the results are one shard of the sweep the settings describe
  // pbr render --json: every option that decided the frame, as given or by default ("render_settings"), which
  // `pbr render --settings` reads back; empty for bench reports.
  std::vector<std::pair<std::string, std::string>> renderSettings;
};

// A digest of the settings that define a sweep's measurements (FNV-1a, 16 hex digits): reports of the same sweep,
// its shards included, carry the same one.
std::string sweepFingerprint(const BenchSettings& settings);

// CSV: a header row, then one row per configuration with five order statistics per pass. Every cell holds a
// value: "skipped" for measurements of a skipped configuration, "n/a" where a quantity does not exist (the cluster
// pass and cluster statistics of brute-force rows).
void writeBenchCsv(std::ostream& out, const BenchReport& report);
// What the CSV's provenance file holds (csv_provenance.hpp): the provenance, the settings, the sweep fingerprint and
// the shard.
KeyValues benchCsvProvenance(const BenchReport& report);

// JSON (schema "pbr-bench/1"): provenance, settings, the sweep's size and fingerprint, the shard ("shard": {"index":
// K, "count": N}, only in a shard's report) and one object per configuration with summaries, every timed frame,
// light statistics and memory; keys are always present, null where the CSV says skipped or n/a.
void writeBenchJson(std::ostream& out, const BenchReport& report);

// A fixed-width table of the median times, light statistics and memory per configuration.
void printBenchTable(std::ostream& out, const BenchReport& report);

}  // namespace pbr
