// The `pbr` binary as a user meets it: exit codes, one-line errors and the captures it writes.
#include <doctest/doctest.h>
#include <stb_image.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "tests/gl_test_context.hpp"

namespace fs = std::filesystem;

namespace {

std::string readFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string shellQuote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// A fresh directory per test case, removed afterwards; ctest runs cases as parallel processes, hence the pid.
class TempDir {
 public:
  TempDir() {
    static int counter = 0;
    const std::string name = "pbr_test_cli_" + std::to_string(::getpid()) + "_" + std::to_string(++counter);
    path_ = fs::temp_directory_path() / name;
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const fs::path& path() const { return path_; }
  std::string file(const std::string& name) const { return (path_ / name).string(); }

 private:
  fs::path path_;
};

struct Run {
  int exitCode = -1;
  std::string out, err;
};

// Runs `pbr` with the given arguments, capturing both streams through files in `dir`.
Run runPbr(const TempDir& dir, const std::vector<std::string>& args) {
  std::string command = shellQuote(PBR_BINARY);
  for (const std::string& a : args) command += " " + shellQuote(a);
  command += " >" + shellQuote(dir.file("stdout.txt")) + " 2>" + shellQuote(dir.file("stderr.txt"));
  const int status = std::system(command.c_str());
  Run run;
  run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.out = readFile(dir.file("stdout.txt"));
  run.err = readFile(dir.file("stderr.txt"));
  return run;
}

bool isOneLine(const std::string& s) {
  return !s.empty() && s.back() == '\n' && s.find('\n') == s.size() - 1;
}

}  // namespace

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

TEST_CASE("cli: render writes PNG, PFM and EXR captures") {
  PBR_REQUIRE_GL();
  const TempDir dir;
  const std::string png = dir.file("f.png"), pfm = dir.file("f.pfm"), exr = dir.file("f.exr");
  const Run run = runPbr(dir, {"render", "--size", "160x90", "--lights", "8", "--out", png, "--hdr", pfm});
  REQUIRE(run.exitCode == 0);

  int w = 0, h = 0, n = 0;
  std::unique_ptr<stbi_uc, void (*)(void*)> pixels(stbi_load(png.c_str(), &w, &h, &n, 4), stbi_image_free);
  REQUIRE(pixels != nullptr);
  CHECK(w == 160);
  CHECK(h == 90);

  // PFM: "PF\n<w> <h>\n<scale>\n" then w*h RGB float32, a negative scale meaning little endian.
  const std::string bytes = readFile(pfm);
  std::istringstream header(bytes);
  std::string magic;
  int pw = 0, ph = 0;
  double scale = 0.0;
  header >> magic >> pw >> ph >> scale;
  REQUIRE(header);
  CHECK(magic == "PF");
  CHECK(pw == 160);
  CHECK(ph == 90);
  CHECK(scale < 0.0);
  const size_t dataStart = static_cast<size_t>(header.tellg()) + 1;  // one whitespace byte ends the header
  const size_t count = static_cast<size_t>(160) * 90 * 3;
  REQUIRE(bytes.size() == dataStart + count * sizeof(float));
  std::vector<float> values(count);  // little endian, as the hosts this builds on
  std::memcpy(values.data(), bytes.data() + dataStart, count * sizeof(float));
  size_t bad = 0, positive = 0;
  for (float v : values) {
    bad += !(std::isfinite(v) && v >= 0.0f);
    positive += v > 0.0f;
  }
  CHECK(bad == 0);
  CHECK(positive > 0);

  REQUIRE(runPbr(dir, {"render", "--size", "160x90", "--lights", "8", "--hdr", exr}).exitCode == 0);
  const std::string exrBytes = readFile(exr);
  REQUIRE(exrBytes.size() >= 4);
  // OpenEXR's magic number 20000630, little endian: the bytes 76 2f 31 01.
  CHECK(exrBytes.compare(0, 4, "\x76\x2f\x31\x01") == 0);
}

TEST_CASE("cli: an HDR capture with an unknown extension fails with exit 1 naming the file") {
  PBR_REQUIRE_GL();
  const TempDir dir;
  const std::string txt = dir.file("f.txt");
  const Run run = runPbr(dir, {"render", "--size", "160x90", "--lights", "8", "--hdr", txt});
  CHECK(run.exitCode == 1);
  CHECK(isOneLine(run.err));
  CHECK(run.err.find(txt) != std::string::npos);
  CHECK_FALSE(fs::exists(txt));
}
