// `pbr render` writing what it renders: PNG, PFM and EXR captures, and the scene of a JSON file.
#include <doctest/doctest.h>
#include <stb_image.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "tests/cli_scene.hpp"
#include "tests/cli_util.hpp"
#include "tests/gl_test_context.hpp"

using namespace pbr::test;
using Run = PbrRun;

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

TEST_CASE("cli: render --out F.jpg writes a JPEG of the frame the PNG holds") {
  PBR_REQUIRE_GL();
  const TempDir dir;
  const std::string png = dir.file("f.png"), jpg = dir.file("f.JPG");
  const std::vector<std::string> frame = {"render", "--size", "160x90", "--lights", "8", "--frames", "1"};
  std::vector<std::string> toPng = frame, toJpg = frame;
  toPng.insert(toPng.end(), {"--out", png});
  toJpg.insert(toJpg.end(), {"--out", jpg});
  REQUIRE(runPbr(dir, toPng).exitCode == 0);
  REQUIRE(runPbr(dir, toJpg).exitCode == 0);
  const std::string bytes = readFile(jpg);
  REQUIRE(bytes.size() > 3);
  CHECK(bytes.compare(0, 3, "\xff\xd8\xff") == 0);  // JPEG's start-of-image marker
  int w = 0, h = 0, n = 0, pw = 0, ph = 0;
  std::unique_ptr<stbi_uc, void (*)(void*)> lossy(stbi_load(jpg.c_str(), &w, &h, &n, 3), stbi_image_free);
  std::unique_ptr<stbi_uc, void (*)(void*)> exact(stbi_load(png.c_str(), &pw, &ph, &n, 3), stbi_image_free);
  REQUIRE(lossy != nullptr);
  REQUIRE(exact != nullptr);
  REQUIRE(w == pw);
  REQUIRE(h == ph);
  // Quality 95 with 4:2:0 chroma: small errors on average, larger only at the edges of coloured highlights.
  double sum = 0.0;
  for (int i = 0; i < w * h * 3; ++i) sum += std::abs(int(lossy.get()[i]) - int(exact.get()[i]));
  MESSAGE("mean absolute difference JPEG - PNG: " << sum / (w * h * 3) << " levels");
  CHECK(sum / (w * h * 3) < 2.0);
}

TEST_CASE("cli: render --scene FILE.json renders the file's scene") {
  PBR_REQUIRE_GL();
  const TempDir dir;
  const std::string scene = dir.write("scene.json", kCliScene), png = dir.file("f.png");
  const Run run = runPbr(dir, {"render", "--scene", scene, "--size", "64x36", "--out", png});
  CHECK(run.exitCode == 0);
  CHECK(run.err.empty());
  CHECK(run.out.find("scene: scene, 64x36, 9 lights") != std::string::npos);
  CHECK(std::filesystem::exists(png));
  const Run more = runPbr(dir, {"render", "--scene", scene, "--size", "64x36", "--lights", "20"});
  CHECK(more.exitCode == 0);
  CHECK(more.out.find("21 lights") != std::string::npos);
}
