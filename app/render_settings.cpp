#include "app/render_settings.hpp"

#include <algorithm>
#include <filesystem>
#include <stdexcept>

#include "app/bench/bench_report_reader.hpp"
#include "core/scene/builtin_scenes.hpp"
#include "core/scene/json_file.hpp"

namespace pbr {

namespace {

// What leaves the frame as it is: where it goes, how it is timed and counted, and the record itself.
constexpr const char* kNotFrameOptions[] = {"--out",   "--hdr",    "--json",          "--settings", "--warmup",
                                            "--frames", "--timing", "--capture-frame", "--stats",    "--egl-platform"};

// "--name" of "--name" or "--name=value".
std::string optionName(const std::string& arg) { return arg.substr(0, arg.find('=')); }

// The options pbr render takes to draw configuration `row` (from 1) of a pbr bench report, read as bench-merge
// reads it: its scene, size, lights, culling, model, shadows and tone curve, and the bench's display (no
// anti-aliasing).
RenderSettings benchRowSettings(const std::string& path, size_t row) {
  const BenchReport report = readBenchReport(path).report;
  if (row < 1 || row > report.results.size()) {
    throw std::runtime_error(path + "#" + std::to_string(row) + ": the report has configurations 1 to " +
                             std::to_string(report.results.size()));
  }
  const BenchConfig& c = report.results[row - 1].config;
  if (c.radiusScale != 1.0f) {
    throw std::runtime_error(path + "#" + std::to_string(row) + ": light radii scaled by " +
                             numberText(c.radiusScale) + " (--constant-density), which pbr render cannot");
  }
  RenderSettings record = {{"--scene", c.scene},
                           {"--size", sizeText(c.size)},
                           {"--lights", std::to_string(c.lights)},
                           {"--culling", toString(c.culling)},
                           {"--model", toString(c.model)},
                           {"--shadows", toString(c.shadows.mode)},
                           {"--shadow-filter", toString(c.shadows.filter)},
                           {"--shadow-atlas", std::to_string(c.shadows.atlasSize)},
                           {"--shadow-cache", c.shadows.cache ? "on" : "off"},
                           {"--tonemap", toString(c.toneCurve)},
                           {"--aa", "none"}};
  if (report.settings.spotShare) record.push_back({"--spot-share", numberText(*report.settings.spotShare)});
  return record;
}

// The render_settings of a report pbr render --json wrote.
RenderSettings reportSettings(const std::string& path) {
  const nlohmann::json doc = readJsonFile(path);
  const auto found = doc.find("render_settings");
  if (found == doc.end() && doc.contains("configurations")) {
    throw std::runtime_error(path + ": a pbr bench report: name one of its configurations, " + path + "#K");
  }
  if (found == doc.end() || !found->is_object()) {
    throw std::runtime_error(path + ": holds no render_settings object (pbr render --json writes one)");
  }
  RenderSettings record;
  for (const auto& [option, value] : found->items()) {
    if (!value.is_string()) throw std::runtime_error(path + ": render_settings." + option + ": expected a string");
    record.push_back({option, value.get<std::string>()});
  }
  return record;
}

}  // namespace

bool decidesFrame(const std::string& option) {
  return std::none_of(std::begin(kNotFrameOptions), std::end(kNotFrameOptions),
                      [&](const char* other) { return option == other; });
}

RenderSettings renderSettings(const std::vector<OptionSpec>& specs, const Args& args) {
  RenderSettings record;
  for (const OptionSpec& spec : specs) {
    if (!decidesFrame(spec.name)) continue;
    if (!args.has(spec.name) && spec.defaultValue.empty()) continue;  // absent: the scene's, or off
    std::string value = spec.metavar.empty() ? "" : args.get(spec.name);
    const bool file = (spec.name == "--scene" && !isBuiltinScene(value)) ||
                      (spec.name == "--environment" && value != "sky" && value != "none");
    if (file && std::filesystem::exists(value)) value = std::filesystem::absolute(value).lexically_normal().string();
    record.push_back({spec.name, value});
  }
  return record;
}

std::vector<std::string> withSettingsFile(const std::vector<OptionSpec>& specs, const std::vector<std::string>& argv) {
  std::string path;
  for (size_t i = 0; i < argv.size(); ++i) {
    if (argv[i] == "--settings" && i + 1 < argv.size()) path = argv[i + 1];
    if (argv[i].rfind("--settings=", 0) == 0) path = argv[i].substr(std::string("--settings=").size());
  }
  if (path.empty()) return argv;
  // F.json#K: configuration K of a bench report.
  size_t row = 0;
  const size_t hash = path.rfind('#');
  if (hash != std::string::npos) {
    const std::string digits = path.substr(hash + 1);
    if (digits.empty() || digits.size() > 6 || digits.find_first_not_of("0123456789") != std::string::npos) {
      throw UsageError("--settings " + path + ": expected F.json or F.json#K, K a configuration of a bench report");
    }
    row = std::stoul(digits);
    path.erase(hash);
  }
  const RenderSettings record = row > 0 ? benchRowSettings(path, row) : reportSettings(path);
  std::vector<std::string> given;
  for (const std::string& arg : argv) {
    if (arg.rfind("--", 0) == 0) given.push_back(optionName(arg));
  }
  std::vector<std::string> out = argv;
  for (const auto& [option, value] : record) {
    const auto spec = std::find_if(specs.begin(), specs.end(), [&](const OptionSpec& s) { return s.name == option; });
    if (spec == specs.end() || !decidesFrame(option)) {
      throw std::runtime_error(path + ": render_settings." + option + ": not an option of pbr render that decides "
                               "the frame");
    }
    if (std::find(given.begin(), given.end(), option) != given.end()) continue;
    out.push_back(option);
    if (!spec->metavar.empty()) out.push_back(value);
  }
  return out;
}

}  // namespace pbr
