#include "app/render_settings.hpp"

#include <algorithm>
#include <filesystem>
#include <stdexcept>

#include "core/builtin_scenes.hpp"
#include "core/json_file.hpp"

namespace pbr {

namespace {

// What leaves the frame as it is: where it goes, how it is timed and counted, and the record itself.
constexpr const char* kNotFrameOptions[] = {"--out",   "--hdr",    "--json",          "--settings", "--warmup",
                                            "--frames", "--timing", "--capture-frame", "--stats",    "--egl-platform"};

// "--name" of "--name" or "--name=value".
std::string optionName(const std::string& arg) { return arg.substr(0, arg.find('=')); }

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
  const nlohmann::json doc = readJsonFile(path);
  const auto record = doc.find("render_settings");
  if (record == doc.end() || !record->is_object()) {
    throw std::runtime_error(path + ": holds no render_settings object (pbr render --json writes one)");
  }
  std::vector<std::string> given;
  for (const std::string& arg : argv) {
    if (arg.rfind("--", 0) == 0) given.push_back(optionName(arg));
  }
  std::vector<std::string> out = argv;
  for (const auto& [option, value] : record->items()) {
    const auto spec = std::find_if(specs.begin(), specs.end(), [&](const OptionSpec& s) { return s.name == option; });
    if (spec == specs.end() || !decidesFrame(option) || !value.is_string()) {
      throw std::runtime_error(path + ": render_settings." + option + ": not an option of pbr render that decides "
                               "the frame, given as a string");
    }
    if (std::find(given.begin(), given.end(), option) != given.end()) continue;
    out.push_back(option);
    if (!spec->metavar.empty()) out.push_back(value.get<std::string>());
  }
  return out;
}

}  // namespace pbr
