// Radiance .hdr input of the IBL module (ibl/radiance_hdr.hpp): the shipped environments load, and every broken
// file fails with one line that names it, before stb_image sees it.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/io/image_output.hpp"
#include "core/scene/assets.hpp"
#include "ibl/environment.hpp"
#include "ibl/radiance_hdr.hpp"
#include "tests/cli_util.hpp"

using pbr::test::TempDir;

namespace {

std::string venice() { return pbr::assetPath("environments/venice_sunset_1k.hdr"); }

std::string readBytes(const std::string& path) { return pbr::test::readFile(path); }

std::string writeBytes(const TempDir& dir, const std::string& name, const std::string& bytes) {
  const std::string path = dir.file(name);
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

// The message of the std::runtime_error that reading `path` throws; fails the test when nothing is thrown.
std::string errorOf(const std::string& path) {
  try {
    pbr::readRadianceHdr(path);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  FAIL("no error for " << path);
  return {};
}

void checkOneLineNaming(const std::string& message, const std::string& path, const std::string& what) {
  CAPTURE(message);
  CHECK(message.rfind(path + ": ", 0) == 0);
  CHECK(message.find('\n') == std::string::npos);
  CHECK(message.find(what) != std::string::npos);
}

// A valid header for a width x height picture, followed by `pixels`.
std::string hdrFile(int width, int height, const std::string& pixels) {
  return "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y " + std::to_string(height) + " +X " + std::to_string(width) + "\n" +
         pixels;
}

}  // namespace

TEST_CASE("ibl hdr: the shipped environments load as 1024x512 finite, non-negative radiance") {
  for (const char* name : {"environments/venice_sunset_1k.hdr", "environments/pedestrian_overpass_1k.hdr"}) {
    CAPTURE(name);
    const pbr::ImageRgbaF image = pbr::readRadianceHdr(pbr::assetPath(name));
    CHECK(image.width == 1024);
    CHECK(image.height == 512);
    REQUIRE(image.pixels.size() == size_t{4} * 1024 * 512);
    double maxLuminance = 0.0;
    bool valid = true;
    for (size_t i = 0; i < image.pixels.size(); i += 4) {
      for (int c = 0; c < 4; ++c) valid = valid && std::isfinite(image.pixels[i + c]) && image.pixels[i + c] >= 0.0f;
      valid = valid && image.pixels[i + 3] == 1.0f;
      maxLuminance = std::max(maxLuminance, 0.2126 * image.pixels[i] + 0.7152 * image.pixels[i + 1] +
                                                0.0722 * image.pixels[i + 2]);
    }
    CHECK(valid);
    // The asset folder's LICENSE.txt gives the maximum luminances: about 44 and 22.
    CHECK(maxLuminance > 10.0);
    CHECK(maxLuminance < 100.0);
  }
}

TEST_CASE("ibl hdr: a truncated file names the file and the scanline where the data ends") {
  const TempDir dir;
  const std::string full = readBytes(venice());
  const std::string first100 = writeBytes(dir, "first100.hdr", full.substr(0, 100));
  checkOneLineNaming(errorOf(first100), first100, "truncated Radiance file (pixel data ends in scanline 0 of 512)");

  const std::string half = writeBytes(dir, "half.hdr", full.substr(0, full.size() / 2));
  checkOneLineNaming(errorOf(half), half, "truncated Radiance file");

  const std::string headerOnly = writeBytes(dir, "header.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n");
  checkOneLineNaming(errorOf(headerOnly), headerOnly, "truncated Radiance header");

  // A run length of 0 would make stb_image loop forever.
  const std::string zeroRun = writeBytes(dir, "zero.hdr", hdrFile(8, 1, std::string("\x02\x02\x00\x08\x00", 5)));
  checkOneLineNaming(errorOf(zeroRun), zeroRun, "corrupt Radiance scanline 0");
}

TEST_CASE("ibl hdr: a PNG renamed, random bytes, an empty file and a missing file are refused by name") {
  const TempDir dir;
  const std::string png = dir.file("image.hdr");
  pbr::ImageRgba8 image{2, 2, std::vector<uint8_t>(16, 200)};
  pbr::writePng(png, image);
  checkOneLineNaming(errorOf(png), png, "not a Radiance RGBE file");

  std::mt19937 rng(7);
  std::string noise(4096, '\0');
  for (char& c : noise) c = static_cast<char>(rng() & 0xFF);
  const std::string random = writeBytes(dir, "random.hdr", noise);
  checkOneLineNaming(errorOf(random), random, "not a Radiance RGBE file");

  const std::string empty = writeBytes(dir, "empty.hdr", "");
  checkOneLineNaming(errorOf(empty), empty, "not a Radiance RGBE file");

  const std::string missing = dir.file("missing.hdr");
  checkOneLineNaming(errorOf(missing), missing, "cannot open: No such file or directory");

  // Environment::fromHdrFile passes the same error on.
  CHECK_THROWS_WITH_AS(pbr::Environment::fromHdrFile(missing),
                       (missing + ": cannot open: No such file or directory").c_str(), std::runtime_error);

  // What is not a regular file is refused before it is read: reading /dev/zero would never end.
  checkOneLineNaming(errorOf("/dev/zero"), "/dev/zero", "not a regular file (a character device)");
  checkOneLineNaming(errorOf(dir.path().string()), dir.path().string(), "not a regular file (a directory)");
}

TEST_CASE("ibl hdr: unsupported headers name what is wrong") {
  const TempDir dir;
  const std::string xyze = writeBytes(dir, "xyze.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_xyze\n\n-Y 1 +X 1\nabcd");
  checkOneLineNaming(errorOf(xyze), xyze, "unsupported Radiance FORMAT=32-bit_rle_xyze");

  const std::string noFormat = writeBytes(dir, "noformat.hdr", "#?RGBE\n\n-Y 1 +X 1\nabcd");
  checkOneLineNaming(errorOf(noFormat), noFormat, "no FORMAT=32-bit_rle_rgbe line");

  const std::string flipped = writeBytes(dir, "flipped.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n+Y 1 +X 1\nabcd");
  checkOneLineNaming(errorOf(flipped), flipped, "unsupported Radiance resolution line \"+Y 1 +X 1\"");

  const std::string badLength = writeBytes(dir, "length.hdr", hdrFile(8, 1, std::string("\x02\x02\x00\x09", 4)));
  checkOneLineNaming(errorOf(badLength), badLength, "is not the width 8");

  // A few bytes of the original format's runs may declare gigapixels: refused before anything is allocated.
  const std::string huge = writeBytes(dir, "huge.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 30000 +X 30000\n"
                                                       "\x80\x80\x80\x81\x01\x01\x01\xff");
  checkOneLineNaming(errorOf(huge), huge,
                     "Radiance image size 30000x30000 is 900000000 pixels, over the limit of 67108864 (1 GiB as float "
                     "RGBA)");
}

TEST_CASE("ibl hdr: flat and run-length pixels decode to the RGBE values they encode") {
  // stb_image decodes (m, e) as m 2^(e - 136).
  const TempDir dir;
  // 2x1 flat: (128, 64, 32, 129) is (1, 0.5, 0.25); e = 0 is black.
  const std::string flat =
      writeBytes(dir, "flat.hdr", hdrFile(2, 1, std::string("\x80\x40\x20\x81\x00\x00\x00\x00", 8)));
  const pbr::ImageRgbaF a = pbr::readRadianceHdr(flat);
  REQUIRE(a.width == 2);
  CHECK(a.pixels[0] == 1.0f);
  CHECK(a.pixels[1] == 0.5f);
  CHECK(a.pixels[2] == 0.25f);
  CHECK(a.pixels[4] == 0.0f);

  // 8x1 run-length: each channel is one run of 8 (count 136): R = 128, G = 0, B = 0, E = 130, so (2, 0, 0).
  const std::string rle =
      writeBytes(dir, "rle.hdr", hdrFile(8, 1, std::string("\x02\x02\x00\x08\x88\x80\x88\x00\x88\x00\x88\x82", 12)));
  const pbr::ImageRgbaF b = pbr::readRadianceHdr(rle);
  REQUIRE(b.width == 8);
  for (int x = 0; x < 8; ++x) {
    CHECK(b.pixels[4 * x] == 2.0f);
    CHECK(b.pixels[4 * x + 1] == 0.0f);
    CHECK(b.pixels[4 * x + 3] == 1.0f);
  }
}

TEST_CASE("ibl hdr: the original format's runs repeat the pixel before them, and sides are read whole") {
  const TempDir dir;
  // 12x1 flat with runs: (128, 64, 32, 129), then (1, 1, 1, 3): three copies, then (1, 1, 1, 0) after it: 0 << 8
  // more, then one pixel, then (1, 1, 1, 7): seven copies of it. 12 pixels from 4 + 4 + 4 + 4 + 4 bytes.
  const std::string pixels("\x80\x40\x20\x81\x01\x01\x01\x03\x01\x01\x01\x00\x40\x40\x40\x81\x01\x01\x01\x07", 20);
  const std::string legacy = writeBytes(dir, "legacy.hdr", hdrFile(12, 1, pixels));
  const pbr::ImageRgbaF a = pbr::readRadianceHdr(legacy);
  REQUIRE(a.width == 12);
  for (int x = 0; x < 12; ++x) {
    CAPTURE(x);
    CHECK(a.pixels[4 * x] == (x < 4 ? 1.0f : 0.5f));
    CHECK(a.pixels[4 * x + 2] == (x < 4 ? 0.25f : 0.5f));
  }
  // A run with no pixel before it, or longer than what is left, is named; so is a side that does not fit.
  const std::string first =
      writeBytes(dir, "first.hdr", hdrFile(2, 1, std::string("\x01\x01\x01\x02\x80\x40\x20\x81", 8)));
  checkOneLineNaming(errorOf(first), first, "corrupt Radiance pixel data (a run of 2 pixels where none precedes it)");
  const std::string longRun =
      writeBytes(dir, "long.hdr", hdrFile(3, 1, std::string("\x80\x40\x20\x81\x01\x01\x01\x05", 8)));
  checkOneLineNaming(errorOf(longRun), longRun, "corrupt Radiance pixel data (a run of 5 pixels where 2 are left)");
  const std::string wrapped =
      writeBytes(dir, "wrapped.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 4294967300 +X 1\nabcd");
  checkOneLineNaming(errorOf(wrapped), wrapped, "Radiance image size 1x4294967300 out of range (at most 32767 a side)");
}
