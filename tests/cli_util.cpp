#include "tests/cli_util.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <iterator>

namespace fs = std::filesystem;

namespace pbr::test {

namespace {

std::string shellQuote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

}  // namespace

TempDir::TempDir() {
  static int counter = 0;
  const std::string name = "pbr_test_" + std::to_string(::getpid()) + "_" + std::to_string(++counter);
  path_ = fs::temp_directory_path() / name;
  fs::remove_all(path_);
  fs::create_directories(path_);
}

TempDir::~TempDir() {
  std::error_code ec;
  fs::remove_all(path_, ec);
}

std::string TempDir::write(const std::string& name, const std::string& text) const {
  const fs::path p = path_ / name;
  fs::create_directories(p.parent_path());
  std::ofstream(p, std::ios::binary) << text;
  return p.string();
}

std::string readFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

PbrRun runPbr(const TempDir& dir, const std::vector<std::string>& args, const std::string& shellSetup) {
  std::string command = shellSetup + shellQuote(PBR_BINARY);
  for (const std::string& a : args) command += " " + shellQuote(a);
  command += " >" + shellQuote(dir.file("stdout.txt")) + " 2>" + shellQuote(dir.file("stderr.txt"));
  const int status = std::system(command.c_str());
  PbrRun run;
  run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.out = readFile(dir.file("stdout.txt"));
  run.err = readFile(dir.file("stderr.txt"));
  return run;
}

bool isOneLine(const std::string& s) { return !s.empty() && s.back() == '\n' && s.find('\n') == s.size() - 1; }

HelpMeaning helpMeaning(const HelpEntry& entry) {
  const std::string swept = "; a comma-separated list, each measured in turn";
  const size_t stated = entry.text.rfind(" (default");
  HelpMeaning m{stated == std::string::npos ? entry.text : entry.text.substr(0, stated)};
  m.swept = m.text.size() > swept.size() && m.text.compare(m.text.size() - swept.size(), swept.size(), swept) == 0;
  if (m.swept) m.text.resize(m.text.size() - swept.size());
  return m;
}

std::vector<HelpEntry> helpEntries(const std::string& help) {
  std::vector<HelpEntry> entries;
  const size_t options = help.find("\noptions:\n");
  if (options == std::string::npos) return entries;
  std::istringstream in(help.substr(options));
  // Args::helpText's layout: "  --name METAVAR", two spaces or more, the description; continuation lines start at
  // its 26th column.
  const std::string continuation(26, ' ');
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("  --", 0) == 0) {
      const size_t nameEnd = line.find(' ', 2);
      const size_t gap = line.find("  ", 2);
      entries.push_back({line.substr(2, nameEnd == std::string::npos ? std::string::npos : nameEnd - 2),
                         line.substr(2, gap == std::string::npos ? std::string::npos : gap - 2),
                         gap == std::string::npos ? "" : line.substr(line.find_first_not_of(' ', gap))});
    } else if (!entries.empty() && line.rfind(continuation, 0) == 0) {
      HelpEntry& last = entries.back();
      last.text += (last.text.empty() ? "" : " ") + line.substr(continuation.size());
    }
  }
  return entries;
}

}  // namespace pbr::test
