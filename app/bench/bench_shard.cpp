#include "app/bench/bench_shard.hpp"

#include <algorithm>
#include <cstdlib>
#include <numeric>

#include "app/args.hpp"

namespace pbr {

namespace {

// Digits only: strtol alone would take " 2", "+2" and "2 " too.
bool parsePart(const std::string& text, long& value) {
  const auto digit = [](char c) { return c >= '0' && c <= '9'; };
  if (text.empty() || text.size() > 9 || !std::all_of(text.begin(), text.end(), digit)) return false;
  value = std::strtol(text.c_str(), nullptr, 10);
  return true;
}

}  // namespace

BenchShard parseShard(const std::string& text) {
  const size_t slash = text.find('/');
  long index = 0, count = 0;
  if (slash == std::string::npos || !parsePart(text.substr(0, slash), index) ||
      !parsePart(text.substr(slash + 1), count) || count < 1 || count > kMaxShards || index < 1 || index > count) {
    throw UsageError("--shard expects K/N, shard K of N with 1 <= K <= N <= " + std::to_string(kMaxShards) +
                     ", got '" + text + "'");
  }
  return {static_cast<int>(index), static_cast<int>(count)};
}

std::vector<size_t> shardPositions(const std::vector<BenchConfig>& sweep, BenchShard shard) {
  // Costs differ by orders of magnitude: more lights cost more, and at equal lights brute force (which shades every
  // light at every pixel) costs more than clustered culling. Configurations are ranked by that expected cost and
  // dealt out like a snake draft (shards 1..N, then N..1, ...), so every shard gets one of each N consecutive ranks
  // and none always picks first. Plain round-robin over the sweep order would not mix: culling and model vary
  // innermost, so with N a multiple of their combinations (4 shards of the default sweep) one shard would get every
  // brute-force PBR configuration and others only clustered ones.
  std::vector<size_t> byCost(sweep.size());
  std::iota(byCost.begin(), byCost.end(), size_t{0});
  std::stable_sort(byCost.begin(), byCost.end(), [&](size_t a, size_t b) {
    if (sweep[a].lights != sweep[b].lights) return sweep[a].lights > sweep[b].lights;
    return sweep[a].culling == Culling::None && sweep[b].culling != Culling::None;
  });
  const size_t count = static_cast<size_t>(shard.count);
  std::vector<size_t> positions;
  for (size_t rank = 0; rank < byCost.size(); ++rank) {
    const size_t seat = rank % count;
    const size_t dealtTo = (rank / count) % 2 == 0 ? seat : count - 1 - seat;
    if (dealtTo + 1 == static_cast<size_t>(shard.index)) positions.push_back(byCost[rank]);
  }
  std::sort(positions.begin(), positions.end());
  return positions;
}

}  // namespace pbr
