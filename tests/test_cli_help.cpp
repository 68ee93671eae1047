// What `pbr <command> --help` says an absent option means, read from the help as a user reads it and compared with
// the values the code itself starts from (the settings structs the commands fill), for every command.
#include <doctest/doctest.h>

#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "app/accuracy/pair_cost_settings.hpp"
#include "app/bench/bench_sweep.hpp"
#include "core/io/context_info.hpp"
#include "post/anti_aliasing.hpp"
#include "reference/brdf_form_names.hpp"
#include "reference/reference_renderer.hpp"
#include "renderer/frame_options.hpp"
#include "renderer/renderer_config.hpp"
#include "tests/cli_util.hpp"

using pbr::test::runPbr;
using pbr::test::TempDir;

namespace {

const std::vector<std::string> kCommands = {"render", "bench", "bench-merge", "experiment", "view", "reference",
                                            "accuracy"};

using pbr::test::HelpEntry;

std::map<std::string, HelpEntry> helpOf(const std::string& command) {
  const TempDir dir;
  const pbr::test::PbrRun run = runPbr(dir, {command, "--help"});
  REQUIRE(run.exitCode == 0);
  std::map<std::string, HelpEntry> entries;
  for (HelpEntry& e : pbr::test::helpEntries(run.out)) entries[e.name] = std::move(e);
  return entries;
}

// The default a help entry states: "V" of "(default V)" or "TEXT" of "(default: TEXT)" at its end, else "".
std::string statedDefault(const HelpEntry& e) {
  std::smatch m;
  return std::regex_search(e.text, m, std::regex("\\(default:? (.*)\\)$")) ? m[1].str() : "";
}

template <typename T, typename Text>
std::string joined(const std::vector<T>& items, Text text) {
  std::string out;
  for (const T& item : items) out += (out.empty() ? "" : ",") + std::string(text(item));
  return out;
}

std::string size(glm::ivec2 s) { return std::to_string(s.x) + "x" + std::to_string(s.y); }

}  // namespace

TEST_CASE("cli help: each default the help states is the value the code starts from, for every command") {
  const pbr::FrameOptions frame;
  const pbr::RendererConfig renderer;
  const pbr::BenchSettings sweep;
  const pbr::PairCostSettings pairCost;
  const pbr::reference::ReferenceOptions reference;
  const std::string display = pbr::toString(pbr::kDisplayAntiAliasing);
  const std::map<std::string, std::map<std::string, std::string>> expected = {
      {"render",
       {{"--model", pbr::toString(frame.model)},
        {"--culling", pbr::toString(pbr::kCommandCulling)},
        {"--tile", pbr::measuredGrid().clusters.tileTrial ? "auto" : std::to_string(renderer.clusters.tileSize)},
        {"--slices", std::to_string(renderer.clusters.slices)},
        {"--hdr-format", pbr::toString(renderer.hdrFormat)},
        {"--gbuffer", pbr::toString(renderer.gbuffer)},
        {"--variant", pbr::toString(frame.variant) + "," + pbr::toString(frame.variant.lobe)},
        {"--aa", display},
        {"--timing", "auto"},
        {"--egl-platform", pbr::toString(pbr::EglPlatform::Auto)}}},
      {"view", {{"--model", pbr::toString(frame.model)}, {"--culling", pbr::toString(pbr::kCommandCulling)},
                {"--aa", display}}},
      {"bench",
       {{"--scene", sweep.scene},
        {"--lights", joined(sweep.lights, [](int n) { return std::to_string(n); })},
        {"--culling", joined(sweep.culling, [](pbr::Culling c) { return pbr::toString(c); })},
        {"--model", joined(sweep.models, [](pbr::ShadingModel m) { return pbr::toString(m); })},
        {"--size", size(sweep.size)},
        {"--warmup", std::to_string(sweep.warmup)},
        {"--frames", std::to_string(sweep.frames)},
        {"--max-seconds", std::to_string(static_cast<int>(sweep.maxSeconds))},
        {"--pair-lights", std::to_string(pairCost.lights)},
        {"--rounds", std::to_string(pairCost.rounds)},
        {"--timing", sweep.timing}}},
      {"accuracy",
       {{"--pair-size", size(pairCost.size)},
        {"--pair-lights", std::to_string(pairCost.lights)},
        {"--threads", std::to_string(reference.threads)}}},
      {"reference",
       {{"--threads", std::to_string(reference.threads)},
        {"--geometry", pbr::reference::toString(reference.geometry)},
        {"--shadows", pbr::toString(pbr::ShadowMode::Auto)},  // the command's, as pbr render's; the library's is none
        {"--variant", pbr::reference::toString(reference.forms)}}},
  };
  // The sweep's --max-seconds default is a whole number of seconds, as the comparison above assumes.
  CHECK(sweep.maxSeconds == static_cast<int>(sweep.maxSeconds));
  for (const auto& [command, defaults] : expected) {
    const auto entries = helpOf(command);
    for (const auto& [option, value] : defaults) {
      CAPTURE(command);
      CAPTURE(option);
      REQUIRE(entries.count(option) == 1);
      CHECK(statedDefault(entries.at(option)) == value);
    }
  }
}

TEST_CASE("cli help: a default is stated once, at the end of its option's description, in every command") {
  for (const std::string& command : kCommands) {
    for (const auto& [option, entry] : helpOf(command)) {
      CAPTURE(command);
      CAPTURE(entry.text);
      const std::regex stated("\\(default[: ]");
      const auto count = std::distance(std::sregex_iterator(entry.text.begin(), entry.text.end(), stated),
                                       std::sregex_iterator());
      CHECK(count <= 1);
      if (count == 1) CHECK_FALSE(statedDefault(entry).empty());
    }
  }
}

TEST_CASE("cli help: every option that takes a value says what its absence means, unless it names an output") {
  // Outputs are written only when asked for, and these choose a mode of their command by being given.
  const std::set<std::string> optional = {"--out", "--hdr", "--json", "--csv", "--trace", "--screenshot",
                                          "--pair-cost"};
  for (const std::string& command : kCommands) {
    for (const auto& [option, entry] : helpOf(command)) {
      CAPTURE(command);
      CAPTURE(option);
      const bool takesValue = entry.synopsis.find(' ') != std::string::npos;
      if (takesValue && !optional.count(option)) CHECK_FALSE(statedDefault(entry).empty());
      if (!takesValue) CHECK(statedDefault(entry).empty());
    }
  }
}

TEST_CASE("cli help: an option means the same in every command that takes it, only its default may differ") {
  std::map<std::string, std::pair<std::string, HelpEntry>> first;  // option -> the first command and its entry
  int shared = 0;
  for (const std::string& command : kCommands) {
    for (const auto& [option, entry] : helpOf(command)) {
      if (option == "--help") continue;  // pbr view lists its keys after it
      HelpEntry e = entry;
      // pbr bench sweeps some options: a comma-separated list of the values the others take, each measured in turn.
      const pbr::test::HelpMeaning meaning = pbr::test::helpMeaning(entry);
      e.text = meaning.text;
      if (meaning.swept) {
        CHECK(command == "bench");
        CHECK(e.synopsis == option + " LIST");
        e.synopsis.clear();
      }
      const auto seen = first.find(option);
      if (seen == first.end()) {
        first.emplace(option, std::make_pair(command, e));
        continue;
      }
      ++shared;
      CAPTURE(option);
      CAPTURE(seen->second.first);
      CAPTURE(command);
      if (!e.synopsis.empty() && !seen->second.second.synopsis.empty()) {
        CHECK(e.synopsis == seen->second.second.synopsis);
      }
      CHECK(e.text == seen->second.second.text);
    }
  }
  CHECK(shared > 40);  // the scene, shading, shadow, display and timing options most commands take
}
