// The `pbr` binary as a user meets it before it renders: help, version, and command lines refused with exit code 2
// and one line on stderr before any context is made.
#include <doctest/doctest.h>

#include <filesystem>
#include <regex>
#include <string>
#include <vector>

#include "tests/cli_util.hpp"

namespace fs = std::filesystem;
using pbr::test::isOneLine;
using pbr::test::runPbr;
using pbr::test::TempDir;
using Run = pbr::test::PbrRun;

TEST_CASE("cli: --help exits 0 and describes the commands") {
  const TempDir dir;
  const Run top = runPbr(dir, {"--help"});
  CHECK(top.exitCode == 0);
  CHECK(top.out.find("usage: pbr") != std::string::npos);
  CHECK(top.err.empty());
  const Run render = runPbr(dir, {"render", "--help"});
  CHECK(render.exitCode == 0);
  CHECK(render.out.find("--size") != std::string::npos);
  CHECK(render.err.empty());
}

TEST_CASE("cli: malformed command lines exit 2 with one line on stderr") {
  const TempDir dir;
  const std::vector<std::vector<std::string>> cases = {
      {"render", "--no-such-option"}, {"render", "--size", "160"},      {"render", "--size", "0x90"},
      {"render", "--size", "160x90x"}, {"render", "--size=axb"},        {"render", "--lights", "-1"},
      {"render", "--lights", "many"},  {"render", "--model", "phong"},  {"render", "--model"},
      {"no-such-command"}};
  for (const auto& args : cases) {
    std::string joined;
    for (const std::string& a : args) joined += a + " ";
    CAPTURE(joined);
    const Run run = runPbr(dir, args);
    CHECK(run.exitCode == 2);
    CHECK(isOneLine(run.err));
    // Usage errors are caught before a context is made or anything is printed.
    CHECK(run.out.empty());
  }
}

TEST_CASE("cli: an HDR capture with an unknown extension fails before rendering with exit 2 naming the file") {
  const TempDir dir;
  const std::string txt = dir.file("f.txt");
  const Run run = runPbr(dir, {"render", "--size", "160x90", "--lights", "8", "--hdr", txt});
  CHECK(run.exitCode == 2);
  CHECK(run.out.empty());
  CHECK(isOneLine(run.err));
  CHECK(run.err.find(txt) != std::string::npos);
  CHECK_FALSE(fs::exists(txt));
}

TEST_CASE("bench: malformed options exit 2 with one line on stderr") {
  const TempDir dir;
  const std::vector<std::vector<std::string>> cases = {
      {"--lights", "64,x"}, {"--lights", "64,,256"}, {"--lights", "-1"},   {"--culling", "fast"},
      {"--model", "phong"}, {"--culling", "none,none"}, {"--frames", "0"}, {"--warmup", "0"},
      {"--max-seconds", "soon"}, {"--timing", "fast"}, {"--size", "big"}, {"--rounds", "3"},
      {"--pair-lights", "8"},   {"--pair-cost", "no-such-variant"}};
  for (const auto& args : cases) {
    std::vector<std::string> argv = {"bench"};
    argv.insert(argv.end(), args.begin(), args.end());
    const Run run = runPbr(dir, argv);
    CAPTURE(args[0]);
    CAPTURE(args[1]);
    CAPTURE(run.err);
    CHECK(run.exitCode == 2);
    CHECK(isOneLine(run.err));
    CHECK(run.out.empty());
  }
}

TEST_CASE("cli: --version names the version and the commit") {
  const TempDir dir;
  const Run run = runPbr(dir, {"--version"});
  CHECK(run.exitCode == 0);
  CHECK(std::regex_search(run.out, std::regex("^pbr [0-9]+\\.[0-9]+\\.[0-9]+ \\(commit ([0-9a-f]{40}|unknown), ")));
  CHECK(isOneLine(run.out));
}
