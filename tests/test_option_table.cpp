// Every command's --help, read as a user reads it, against the one option table: each option a command lists is a
// row of the table with the row's value form and meaning, in the command's order, and every row serves a command.
#include <doctest/doctest.h>

#include <algorithm>
#include <set>
#include <string>
#include <vector>

#include "app/option_table.hpp"
#include "tests/cli_util.hpp"

namespace {

const std::vector<pbr::Command> kCommands = {pbr::Command::Render,     pbr::Command::Bench,
                                             pbr::Command::BenchMerge, pbr::Command::Experiment,
                                             pbr::Command::View,       pbr::Command::Reference,
                                             pbr::Command::Accuracy};

// A help's description is the row's text wrapped at spaces: compare word by word.
std::vector<std::string> words(const std::string& text) {
  std::vector<std::string> out;
  std::string word;
  for (char c : text + " ") {
    if (c != ' ') word += c;
    else if (!word.empty()) out.push_back(std::move(word)), word.clear();
  }
  return out;
}

}  // namespace

TEST_CASE("option table: every command's --help lists rows of the one table, and every row serves a command") {
  const std::vector<pbr::OptionSpec>& table = pbr::optionTable();
  std::set<std::string> taken;
  for (const pbr::Command command : kCommands) {
    const pbr::test::TempDir dir;
    const std::string name = pbr::toString(command);
    const pbr::test::PbrRun run = pbr::test::runPbr(dir, {name, "--help"});
    REQUIRE(run.exitCode == 0);
    std::vector<pbr::test::HelpEntry> help = pbr::test::helpEntries(run.out);
    REQUIRE_FALSE(help.empty());
    CHECK(help.back().name == "--help");
    help.pop_back();
    CAPTURE(name);
    REQUIRE(help.size() == pbr::commandOptions(command).size());
    for (size_t i = 0; i < help.size(); ++i) {
      const pbr::test::HelpEntry& entry = help[i];
      CAPTURE(entry.name);
      CHECK(entry.name == pbr::commandOptions(command)[i].name);  // the command's order
      const auto row = std::find_if(table.begin(), table.end(),
                                    [&](const pbr::OptionSpec& s) { return s.name == entry.name; });
      REQUIRE(row != table.end());
      taken.insert(row->name);
      // pbr bench sweeps some options: the row's meaning, then how a list of its values is measured.
      const pbr::test::HelpMeaning meaning = pbr::test::helpMeaning(entry);
      std::string metavar = row->metavar;
      if (meaning.swept) {
        CHECK(name == "bench");
        metavar = "LIST";
      }
      CHECK(entry.synopsis == row->name + (metavar.empty() ? "" : " " + metavar));
      CHECK(words(meaning.text) == words(row->help));
    }
  }
  for (const pbr::OptionSpec& row : table) {
    CAPTURE(row.name);
    CHECK(taken.count(row.name) == 1);
  }
}
