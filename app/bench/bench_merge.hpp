#pragma once
#include <string>
#include <vector>

#include "app/bench/bench_report_reader.hpp"

namespace pbr {

// One shard's report as `pbr bench --shard K/N --json F` wrote it.
struct ShardFile {
  std::string path;
  BenchReportFile file;  // file.report.shard is set
};

// Reads `path` and checks that it is a shard's report: written with --shard, its settings giving the sweep
// fingerprint it states, and its configurations those that shard measures. Throws with one line naming the file.
ShardFile readShardFile(const std::string& path);

// The report the unsharded sweep would have written: the settings the shards share, every result in sweep order,
// and each provenance value, listed per shard where shards differ ("shards 1, 3: A; shard 2: B"), with
// merged_shards naming the files. Throws std::runtime_error with one line naming a file and the problem when the
// shards are of different sweeps or counts, a shard is given twice or missing, or, unless `allowMixed`, they were
// measured on different renderers or builds (or, with a CPU rasterizer, CPUs).
BenchReport mergeShards(const std::vector<ShardFile>& shards, bool allowMixed);

}  // namespace pbr
