// OpenEXR environments (ibl/openexr_image.*): the same radiance as an .exr and as an .hdr lights a frame alike,
// and a damaged, oversized, self-contradicting or non-finite file is named in one line.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/io/image_output.hpp"
#include "core/scene/assets.hpp"
#include "core/scene/builtin_scenes.hpp"
#include "ibl/openexr_image.hpp"
#include "ibl/radiance_hdr.hpp"
#include "tests/cli_util.hpp"
#include "tests/gl_test_context.hpp"
#include "tests/render_util.hpp"

using pbr::test::TempDir;

namespace {

std::string errorOf(const std::string& path) {
  try {
    pbr::readEnvironmentImage(path);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("ibl exr: an environment written as OpenEXR lights the frame as its Radiance file does") {
  PBR_REQUIRE_GL();
  const TempDir dir;
  const std::string hdr = pbr::assetPath("environments/venice_sunset_1k.hdr");
  const pbr::ImageRgbaF radiance = pbr::readRadianceHdr(hdr);
  // Float32 planes: the same values, read back through tinyexr.
  const std::string exr = dir.file("venice.exr");
  pbr::writeHdr(exr, radiance);
  const pbr::ImageRgbaF read = pbr::readEnvironmentImage(exr);
  REQUIRE(read.width == radiance.width);
  REQUIRE(read.height == radiance.height);
  CHECK(read.pixels == radiance.pixels);
  // Chosen by the magic number whatever the name: an OpenEXR file named .hdr is read as OpenEXR.
  const std::string misnamed = dir.write("venice-exr.hdr", pbr::test::readFile(exr));
  CHECK(pbr::readEnvironmentImage(misnamed).pixels == radiance.pixels);

  pbr::Scene scene = pbr::makeBuiltinScene("helmet");
  scene.environment = pbr::EnvironmentDesc{};
  scene.environment->file = hdr;
  const pbr::test::RenderedFrame fromHdr = pbr::test::renderScene(scene, {96, 54}, {});
  scene.environment->file = exr;
  const pbr::test::RenderedFrame fromExr = pbr::test::renderScene(scene, {96, 54}, {});
  CHECK(fromExr.hdr.pixels == fromHdr.hdr.pixels);
}

TEST_CASE("ibl exr: damaged, oversized and non-finite OpenEXR files are named in one line") {
  const TempDir dir;
  pbr::ImageRgbaF image{4, 2, std::vector<float>(32, 0.25f)};
  image.pixels[0] = -1.0f;
  image.pixels[5] = std::numeric_limits<float>::quiet_NaN();
  image.pixels[10] = std::numeric_limits<float>::infinity();
  const std::string path = dir.file("odd.exr");
  pbr::writeHdr(path, image);
  {
    pbr::test::CapturedStderr err;
    const pbr::ImageRgbaF read = pbr::readEnvironmentImage(path);
    CHECK(read.pixels[0] == 0.0f);
    CHECK(read.pixels[5] == 0.0f);
    CHECK(read.pixels[10] == 0.0f);
    CHECK(read.pixels[1] == 0.25f);
    CHECK(err.text() == path + ": 3 channel values negative, NaN or infinite, read as 0 (an environment's radiance "
                               "is finite and at least 0)\n");
  }
  const std::string bytes = pbr::test::readFile(path);
  // Cut inside the pixel data, and inside the header.
  const std::string cut = dir.write("cut.exr", bytes.substr(0, bytes.size() - 20));
  const std::string message = errorOf(cut);
  CHECK(message.rfind(cut + ": cannot decode the OpenEXR image: ", 0) == 0);
  CHECK(message.find('\n') == std::string::npos);
  const std::string header = dir.write("header.exr", bytes.substr(0, 40));
  CHECK(errorOf(header).rfind(header + ": damaged OpenEXR header: ", 0) == 0);
  // A data window of 40000 x 2 declared in an otherwise valid file: refused before tinyexr allocates.
  std::string wide = bytes;
  const size_t window = wide.find("dataWindow");
  REQUIRE(window != std::string::npos);
  const size_t maxX = window + std::string("dataWindow").size() + 1 + std::string("box2i").size() + 1 + 4 + 8;
  const int32_t x = 39999;
  wide.replace(maxX, 4, std::string(reinterpret_cast<const char*>(&x), 4));
  const std::string widePath = dir.write("wide.exr", wide);
  CHECK(errorOf(widePath) == widePath + ": OpenEXR image size 40000x2 out of range (at most 32767 a side)");
  // 30000 x 3000 fits the format's sides but not the environments' pixel limit.
  const int32_t wideX = 29999, tallY = 2999;
  wide.replace(maxX, 4, std::string(reinterpret_cast<const char*>(&wideX), 4));
  wide.replace(maxX + 4, 4, std::string(reinterpret_cast<const char*>(&tallY), 4));
  const std::string overPath = dir.write("over.exr", wide);
  CHECK(errorOf(overPath) == overPath + ": OpenEXR image size 30000x3000 is 90000000 pixels, over the limit of "
                                        "67108864 (1 GiB as float RGBA)");
  // Header fields that contradict each other, on which tinyexr would assert: refused, naming the field.
  const auto withField = [&](const std::string& name, const std::string& kind, const std::string& value, bool tiled) {
    std::string edited = bytes;
    if (tiled) edited[5] = char(edited[5] | 0x02);  // the version field's tiled bit (bit 9)
    const uint32_t size = uint32_t(value.size());
    edited.insert(8, name + '\0' + kind + '\0' + std::string(reinterpret_cast<const char*>(&size), 4) + value);
    return dir.write(name + "-" + std::to_string(edited.size()) + ".exr", edited);
  };
  const std::string typed = withField("type", "string", "tiledimage", false);
  CHECK(errorOf(typed) == typed + ": OpenEXR header field type is \"tiledimage\", but the header describes a "
                                  "scanline image");
  // tinyexr converts the fields it read before damage it stops at: those are checked too.
  std::string cutShort = bytes;
  cutShort.insert(8, std::string("type\0string\0\2\0\0\0ow", 18) + std::string("x\0y\0\xff\xff\xff\x7f", 8));
  const std::string damaged = dir.write("damaged.exr", cutShort);
  CHECK(errorOf(damaged) == damaged + ": OpenEXR header field type is \"ow\", but the header describes a "
                                      "scanline image");
  // It also stops at a compression it does not know and at a channel list it cannot parse, before a later type field
  // that would have replaced the damaged one.
  const std::string laterType = std::string("type\0string\0\15\0\0\0scanlineimage", 29);
  const std::string damages[] = {std::string("compression\0compression\0\1\0\0\0\11", 29),
                                 std::string("channels\0chlist\0\4\0\0\0R\0\0\0", 24),
                                 std::string("channels\0chlist\0\1\0\0\0\0", 21)};
  for (const std::string& damage : damages) {
    std::string early = bytes;
    early.insert(8, std::string("type\0string\0\2\0\0\0ow", 18) + damage + laterType);
    const std::string earlyPath = dir.write("early-type.exr", early);
    CHECK(errorOf(earlyPath) == earlyPath + ": OpenEXR header field type is \"ow\", but the header describes a "
                                            "scanline image");
  }
  // An empty channel list after one with entries is read on (tinyexr gathers every list's entries in one).
  std::string emptyList = bytes;
  const std::string channel = std::string("R\0", 2) + std::string("\2\0\0\0\0\0\0\0\1\0\0\0\1\0\0\0", 16);
  emptyList.insert(8, std::string("channels\0chlist\0\23\0\0\0", 20) + channel + std::string(1, '\0') +
                          std::string("channels\0chlist\0\1\0\0\0\0", 21) +
                          std::string("type\0string\0\12\0\0\0tiledimage", 26));
  const std::string emptyListPath = dir.write("empty-list.exr", emptyList);
  CHECK(errorOf(emptyListPath) == emptyListPath + ": OpenEXR header field type is \"tiledimage\", but the header "
                                                  "describes a scanline image");
  // A type field past tinyexr's limit of 1024 attributes is not read: the one before it is what tinyexr converts.
  std::string many = bytes;
  std::string filler;
  for (int i = 1; i < 1024; ++i) filler += std::string("a\0b\0\1\0\0\0x", 9);
  many.insert(8, std::string("type\0string\0\2\0\0\0ow", 18) + filler + laterType);
  const std::string manyPath = dir.write("many-attributes.exr", many);
  CHECK(errorOf(manyPath) == manyPath + ": OpenEXR header field type is \"ow\", but the header describes a "
                                        "scanline image");
  // A scanline image's chunkCount sizes tinyexr's offset table before anything compares it with the file.
  const uint32_t billion = 1000000000u;
  const std::string count(reinterpret_cast<const char*>(&billion), 4);
  const std::string chunks = withField("chunkCount", "int", count, false);
  const std::string chunksError = errorOf(chunks);
  CHECK(chunksError.rfind(chunks + ": OpenEXR header field chunkCount says 1000000000 blocks, but the file has room "
                                   "for ", 0) == 0);
  CHECK(chunksError.find(" block offsets") != std::string::npos);
  const std::string shortTiles = withField("tiles", "tiledesc", std::string(4, '\2'), true);
  CHECK(errorOf(shortTiles) == shortTiles + ": OpenEXR header field tiles holds 4 bytes (a tile description is 9)");
  const std::string levelMode = withField("tiles", "tiledesc", std::string("\2\0\0\0\2\0\0\0\3", 9), true);
  CHECK(errorOf(levelMode) == levelMode + ": OpenEXR header field tiles names level mode 3 (0 to 2 are defined)");
  const std::string noTile = withField("tiles", "tiledesc", std::string("\0\0\0\0\2\0\0\0\0", 9), true);
  CHECK(errorOf(noTile) == noTile + ": OpenEXR tile size 0x2 out of range (1 to 32767 a side)");
  const std::string notExr = dir.write("plain.exr", "not an image");
  CHECK(errorOf(notExr) == notExr + ": not an OpenEXR file (no EXR magic number)");
}

namespace {

// A 2x2 OpenEXR image of one float channel Y in 2x1 tiles (one level, uncompressed), written field by field: the
// values 1, 2 in its first row, 3, 4 in its second.
std::string tiledExr() {
  std::string out("\x76\x2f\x31\x01\x02\x02\x00\x00", 8);  // magic; version 2, tiled
  const auto i32 = [](int32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
  const auto f32 = [](float v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
  const auto field = [&](const std::string& name, const std::string& type, const std::string& value) {
    out += name + '\0' + type + '\0' + i32(int32_t(value.size())) + value;
  };
  field("channels", "chlist", std::string("Y\0", 2) + i32(2) + std::string(4, '\0') + i32(1) + i32(1) + '\0');
  field("compression", "compression", std::string(1, '\0'));
  field("dataWindow", "box2i", i32(0) + i32(0) + i32(1) + i32(1));
  field("displayWindow", "box2i", i32(0) + i32(0) + i32(1) + i32(1));
  field("lineOrder", "lineOrder", std::string(1, '\0'));
  field("pixelAspectRatio", "float", f32(1.0f));
  field("screenWindowCenter", "v2f", f32(0.0f) + f32(0.0f));
  field("screenWindowWidth", "float", f32(1.0f));
  field("tiles", "tiledesc", i32(2) + i32(1) + std::string(1, '\0'));
  out += '\0';
  const size_t table = out.size(), first = table + 16, blockSize = 20 + 8;
  for (const uint64_t offset : {uint64_t(first), uint64_t(first + blockSize)}) {
    out += std::string(reinterpret_cast<const char*>(&offset), 8);
  }
  for (int32_t row = 0; row < 2; ++row) {
    out += i32(0) + i32(row) + i32(0) + i32(0) + i32(8) + f32(float(2 * row + 1)) + f32(float(2 * row + 2));
  }
  return out;
}

}  // namespace

TEST_CASE("ibl exr: tiled files are read, and a tile block naming a tile outside its level is refused") {
  const TempDir dir;
  const std::string bytes = tiledExr();
  const pbr::ImageRgbaF image = pbr::readEnvironmentImage(dir.write("tiled.exr", bytes));
  REQUIRE(image.width == 2);
  REQUIRE(image.height == 2);
  for (int p = 0; p < 4; ++p) CHECK(image.pixels[size_t(4 * p)] == float(p + 1));
  // tinyexr takes a block's own coordinates: the second block moved one row down names a tile of no height, on
  // which it asserts; one far off overflows its arithmetic.
  for (const int32_t row : {2, -1, 1 << 30}) {
    std::string moved = bytes;
    const size_t secondBlock = moved.size() - 28;
    moved.replace(secondBlock + 4, 4, std::string(reinterpret_cast<const char*>(&row), 4));
    const std::string path = dir.write("moved.exr", moved);
    CHECK(errorOf(path) == path + ": OpenEXR tile block 1 names tile (0, " + std::to_string(row) +
                               ") of level (0, 0), which has 1x2 tiles");
  }
}
