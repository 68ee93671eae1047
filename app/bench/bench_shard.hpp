#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "app/bench/bench_sweep.hpp"

namespace pbr {

// One of `count` disjoint parts of a sweep, `index` counted from 1: what `pbr bench --shard K/N` measures, so that
// N processes or machines share a sweep and `pbr bench-merge` joins their reports.
struct BenchShard {
  int index = 1;
  int count = 1;
  std::string text() const { return std::to_string(index) + "/" + std::to_string(count); }
};

constexpr int kMaxShards = 1 << 20;

// "K/N" with 1 <= K <= N <= kMaxShards; anything else throws UsageError naming --shard.
BenchShard parseShard(const std::string& text);

// The positions in `sweep` (as sweepConfigs lists it) that shard `shard` measures, ascending. Shards 1..N of one
// sweep are disjoint and together hold every position; the assignment depends on the configurations alone, so
// every process of a sweep computes the same one.
std::vector<size_t> shardPositions(const std::vector<BenchConfig>& sweep, BenchShard shard);

}  // namespace pbr
