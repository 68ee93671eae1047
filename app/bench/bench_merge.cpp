#include "app/bench/bench_merge.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "core/io/context_info.hpp"
#include "core/scene/json_text.hpp"
#include "app/provenance.hpp"

namespace pbr {

namespace {

[[noreturn]] void fail(const std::string& message) { throw std::runtime_error(message); }

// Measurements are comparable only from the same renderer and the same build. A CPU rasterizer's times are the
// CPU's, and its GL strings do not name it: the CPU model must match too.
std::vector<std::string> comparabilityKeys(const Provenance& provenance) {
  std::vector<std::string> keys = {"gl_renderer", "gl_version", "gl_vendor",  "version",
                                   "build_type",  "compiler",   "git_commit", "git_dirty"};
  if (isSoftwareRenderer(provenance.get("gl_renderer"))) keys.push_back("cpu_model");
  return keys;
}

// The first setting in which two sweeps differ, as "lights [4,16] there, [4,8] here".
std::string settingsDifference(const nlohmann::json& there, const nlohmann::json& here) {
  for (const auto& [key, value] : there.items()) {
    const auto other = here.find(key);
    if (other == here.end()) return key + " " + quoteJson(value) + " there, absent here";
    if (*other != value) return key + " " + quoteJson(value) + " there, " + quoteJson(*other) + " here";
  }
  return "settings that give another fingerprint";
}

std::string joinedIndices(const std::vector<int>& indices) {
  std::string out;
  for (int i : indices) out += (out.empty() ? "" : ", ") + std::to_string(i);
  return out;
}

// The JSON keeps provenance keys sorted; a report lists them in the order collectProvenance makes them, which an
// empty context's provenance shows, then any others (load_average_end, ...) in the shards' order.
std::vector<std::string> provenanceKeys(const std::vector<const ShardFile*>& shards) {
  std::vector<std::string> keys;
  for (const auto& [key, value] : collectProvenance(ContextInfo{}, TimingMode::Serializing).entries) {
    keys.push_back(key);
  }
  for (const ShardFile* s : shards) {
    for (const auto& [key, value] : s->file.report.provenance.entries) {
      if (std::find(keys.begin(), keys.end(), key) == keys.end()) keys.push_back(key);
    }
  }
  return keys;
}

// Each key's value where every shard agrees; otherwise the values with the shards that measured them.
Provenance mergedProvenance(const std::vector<const ShardFile*>& shards) {
  Provenance merged;
  for (const std::string& key : provenanceKeys(shards)) {
    std::vector<std::pair<std::string, std::vector<int>>> values;
    for (size_t i = 0; i < shards.size(); ++i) {
      const std::string value = shards[i]->file.report.provenance.get(key);
      auto same = std::find_if(values.begin(), values.end(), [&](const auto& v) { return v.first == value; });
      if (same == values.end()) {
        values.emplace_back(value, std::vector<int>{});
        same = values.end() - 1;
      }
      same->second.push_back(static_cast<int>(i) + 1);
    }
    if (values.size() == 1 && values[0].first.empty()) continue;
    std::string text = values[0].first;
    if (values.size() > 1) {
      text.clear();
      for (const auto& [value, indices] : values) {
        text += (text.empty() ? "" : "; ") + std::string(indices.size() > 1 ? "shards " : "shard ") +
                joinedIndices(indices) + ": " + (value.empty() ? "absent" : value);
      }
    }
    merged.set(key, text);
  }
  std::string files;
  for (const ShardFile* s : shards) files += (files.empty() ? "" : ", ") + s->path;
  merged.set("merged_shards", std::to_string(shards.size()) + ": " + files);
  return merged;
}

}  // namespace

ShardFile readShardFile(const std::string& path) {
  ShardFile shard{path, readBenchReport(path)};
  const BenchReport& report = shard.file.report;
  if (!report.shard) fail(path + ": not a shard's report (written without pbr bench --shard)");
  if (shard.file.sweepFingerprint != sweepFingerprint(report.settings)) {
    fail(path + ": its settings do not give the sweep fingerprint it states (" + shard.file.sweepFingerprint +
         "): the file was edited");
  }
  const std::vector<BenchConfig> sweep = sweepConfigs(report.settings);
  const std::vector<size_t> positions = shardPositions(sweep, *report.shard);
  bool matches = positions.size() == report.results.size();
  for (size_t i = 0; matches && i < positions.size(); ++i) {
    const BenchConfig& want = sweep[positions[i]];
    const BenchConfig& have = report.results[i].config;
    matches = want.label() == have.label() && want.scene == have.scene && want.size == have.size &&
              want.radiusScale == have.radiusScale;
  }
  if (!matches) {
    fail(path + ": its configurations are not the " + std::to_string(positions.size()) + " that shard " +
         report.shard->text() + " of its sweep measures");
  }
  return shard;
}

BenchReport mergeShards(const std::vector<ShardFile>& shards, bool allowMixed) {
  if (shards.empty()) fail("no shards to merge");
  const ShardFile& first = shards.front();
  const BenchShard firstShard = *first.file.report.shard;
  std::vector<const ShardFile*> byIndex(static_cast<size_t>(firstShard.count), nullptr);
  for (const ShardFile& s : shards) {
    const BenchShard shard = *s.file.report.shard;
    if (shard.count != firstShard.count) {
      fail(s.path + ": shard " + shard.text() + " of a sweep in " + std::to_string(shard.count) + " shards, but " +
           first.path + " is shard " + firstShard.text());
    }
    if (s.file.sweepFingerprint != first.file.sweepFingerprint) {
      fail(s.path + ": a shard of another sweep than " + first.path + " (" +
           settingsDifference(first.file.settings, s.file.settings) + ")");
    }
    const ShardFile*& slot = byIndex[static_cast<size_t>(shard.index - 1)];
    if (slot) fail(s.path + ": shard " + shard.text() + " again, already given as " + slot->path);
    if (!allowMixed) {
      for (const std::string& key : comparabilityKeys(first.file.report.provenance)) {
        const std::string here = s.file.report.provenance.get(key), there = first.file.report.provenance.get(key);
        if (here != there) {
          fail(s.path + ": measured with " + key + " '" + here + "', " + first.path + " with '" + there +
               "' (--allow-mixed merges them anyway)");
        }
      }
    }
    slot = &s;
  }
  std::vector<int> missing, given;
  for (size_t i = 0; i < byIndex.size(); ++i) (byIndex[i] ? given : missing).push_back(static_cast<int>(i) + 1);
  if (!missing.empty()) {
    const auto shardWord = [](const std::vector<int>& v) { return std::string(v.size() > 1 ? "shards " : "shard "); };
    fail(shardWord(missing) + joinedIndices(missing) + " of " + std::to_string(firstShard.count) +
         " missing (the files given hold " + shardWord(given) + joinedIndices(given) + ")");
  }

  BenchReport merged;
  merged.settings = first.file.report.settings;
  merged.provenance = mergedProvenance(byIndex);
  const std::vector<BenchConfig> sweep = sweepConfigs(merged.settings);
  merged.results.resize(sweep.size());
  for (const ShardFile* s : byIndex) {
    const std::vector<size_t> positions = shardPositions(sweep, *s->file.report.shard);
    for (size_t i = 0; i < positions.size(); ++i) {
      merged.results[positions[i]] = s->file.report.results[i];
      merged.results[positions[i]].shard = s->file.report.shard->index;
    }
  }
  return merged;
}

}  // namespace pbr
