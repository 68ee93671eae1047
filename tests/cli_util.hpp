#pragma once
#include <filesystem>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace pbr::test {

// A fresh directory per test case, removed afterwards; ctest runs cases as parallel processes, hence the pid.
class TempDir {
 public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::filesystem::path& path() const { return path_; }
  std::string file(const std::string& name) const { return (path_ / name).string(); }
  // Writes `text` to `name` (creating its folders) and returns the file's path.
  std::string write(const std::string& name, const std::string& text) const;

 private:
  std::filesystem::path path_;
};

std::string readFile(const std::filesystem::path& path);

// Holds what std::cerr, where the loaders' warnings go, receives while it lives.
class CapturedStderr {
 public:
  CapturedStderr() : saved_(std::cerr.rdbuf(text_.rdbuf())) {}
  ~CapturedStderr() { std::cerr.rdbuf(saved_); }
  CapturedStderr(const CapturedStderr&) = delete;
  CapturedStderr& operator=(const CapturedStderr&) = delete;
  std::string text() const { return text_.str(); }

 private:
  std::ostringstream text_;
  std::streambuf* saved_;
};

struct PbrRun {
  int exitCode = -1;
  std::string out, err;
};

// Runs the `pbr` binary with `args`, capturing both streams through files in `dir`. `shellSetup` runs first in the
// same shell (resource limits: "ulimit -v 4000000;").
PbrRun runPbr(const TempDir& dir, const std::vector<std::string>& args, const std::string& shellSetup = "");

// True for exactly one newline-terminated line.
bool isOneLine(const std::string& s);

// One option of a command's help, as a user reads it: its name ("--size"), the words before its description
// ("--size WxH") and the description, continuation lines joined.
struct HelpEntry {
  std::string name, synopsis, text;
};

// The options a help text lists under "options:", in its order.
std::vector<HelpEntry> helpEntries(const std::string& help);

// What a help entry says its option means: the description without its default clause and, for an option pbr bench
// sweeps, without the suffix that says so (`swept`).
struct HelpMeaning {
  std::string text;
  bool swept = false;
};
HelpMeaning helpMeaning(const HelpEntry& entry);

}  // namespace pbr::test
