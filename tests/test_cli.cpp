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

#include "tests/cli_util.hpp"
#include "tests/gl_test_context.hpp"

namespace fs = std::filesystem;
using pbr::test::isOneLine;
using pbr::test::readFile;
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
