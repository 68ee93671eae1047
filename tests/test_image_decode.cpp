// The image decoder refuses corrupt files with a reason, including those that would make stb_image write out of
// bounds, and still decodes the real textures of the shared models.
#include <doctest/doctest.h>
#include <stb_image_write.h>
#include <webp/decode.h>
#include <webp/encode.h>

#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/io/image_output.hpp"
#include "core/scene/assets.hpp"

namespace {

std::string decodeError(const std::vector<unsigned char>& bytes) {
  try {
    pbr::decodeImage(bytes.data(), bytes.size(), "t.jpg");
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("image decode: a JPEG Huffman table with more than 256 codes is refused before stb_image builds it") {
  // SOI, DHT of length 18 whose counts start 0xa2, 0x80 (290 codes); then the file ends (a fuzzer's find).
  const std::vector<unsigned char> jpeg = {0xFF, 0xD8, 0xFF, 0xC4, 0x00, 0x12, 0x00, 0xA2, 0x80};
  CHECK(decodeError(jpeg) == "t.jpg: cannot decode image: truncated JPEG marker segment");
  std::vector<unsigned char> whole = {0xFF, 0xD8, 0xFF, 0xC4, 0x00, 0x13, 0x00, 0xA2, 0x80};
  whole.resize(whole.size() + 14, 0);
  CHECK(decodeError(whole) == "t.jpg: cannot decode image: a JPEG Huffman table with 290 codes (at most 256)");
  // Without a decoder reason the message still names the file.
  CHECK(decodeError({0xFF, 0xD8, 0xFF, 0xD9}).rfind("t.jpg: cannot decode image", 0) == 0);
}

TEST_CASE("image decode: fill bytes before the JPEG start-of-image marker do not hide a bad Huffman table") {
  // stb_image reads any run of 0xFF before a marker, SOI too, so this is a JPEG to it (a fuzzer's find in CI).
  std::vector<unsigned char> jpeg = {0xFF, 0xFF, 0xFF, 0xD8, 0xFF, 0xC4, 0x00, 0x13, 0x00, 0xA2, 0x80};
  jpeg.resize(jpeg.size() + 14, 0);
  CHECK(decodeError(jpeg) == "t.jpg: cannot decode image: a JPEG Huffman table with 290 codes (at most 256)");
  CHECK(decodeError({0xFF, 0xFF, 0xD8, 0xFF, 0xC4, 0x00, 0x12, 0x00, 0xA2, 0x80}) ==
        "t.jpg: cannot decode image: truncated JPEG marker segment");
}

namespace {

// SOI, a frame header of one 1x1 component (SOF0 sequential or SOF2 progressive), a DHT segment defining only DC
// table 0 with one code, then a scan of that component naming DC table 0 and AC table 0 over spectral band
// [start, end] and the given successive approximation byte, then EOI.
std::vector<unsigned char> jpegWithOnlyDcTable(unsigned frameMarker, unsigned char start, unsigned char end,
                                               unsigned char approximation) {
  std::vector<unsigned char> jpeg = {0xFF, 0xD8, 0xFF, static_cast<unsigned char>(frameMarker), 0x00, 0x0B, 8, 0, 1,
                                     0, 1, 1, 1, 0x11, 0};
  // Class and id, 16 code counts (one code of length 1), its symbol.
  std::vector<unsigned char> dht = {0xFF, 0xC4, 0x00, 0x14, 0x00, 1};
  dht.resize(dht.size() + 15 + 1, 0);
  const std::vector<unsigned char> sos = {0xFF, 0xDA, 0x00, 0x08, 1, 1, 0x00, start, end, approximation};
  jpeg.insert(jpeg.end(), dht.begin(), dht.end());
  jpeg.insert(jpeg.end(), sos.begin(), sos.end());
  jpeg.insert(jpeg.end(), {0x00, 0xFF, 0xD9});
  return jpeg;
}

}  // namespace

TEST_CASE("image decode: a JPEG scan naming a Huffman table no DHT segment defines is refused") {
  // stb_image would decode with the table's uninitialised memory (UBSan: index 918 out of bounds of values[256],
  // a fuzzer's find in CI, fuzz/regressions/texture_fuzzer/jpeg-scan-uses-undefined-huffman-table.jpg).
  const std::string undefinedAc =
      "t.jpg: cannot decode image: a JPEG scan uses AC Huffman table 0, which no DHT segment defines";
  CHECK(decodeError(jpegWithOnlyDcTable(0xC0, 0, 63, 0)) == undefinedAc);
  CHECK(decodeError(jpegWithOnlyDcTable(0xC2, 1, 5, 0)) == undefinedAc);  // a progressive AC scan
  // A progressive DC scan decodes with its DC table only (first pass) or none (refinement): not this refusal.
  CHECK(decodeError(jpegWithOnlyDcTable(0xC2, 0, 0, 0)).find("Huffman") == std::string::npos);
  CHECK(decodeError(jpegWithOnlyDcTable(0xC2, 0, 0, 0x10)).find("Huffman") == std::string::npos);
  std::vector<unsigned char> noDc = jpegWithOnlyDcTable(0xC2, 0, 0, 0);
  noDc[19] = 0x01;  // the DHT now defines DC table 1
  CHECK(decodeError(noDc) ==
        "t.jpg: cannot decode image: a JPEG scan uses DC Huffman table 0, which no DHT segment defines");
}

TEST_CASE("image decode: the shared models' JPEG and PNG textures decode") {
  const std::filesystem::path assets(pbr::assetDir());
  if (!std::filesystem::exists(assets / "DamagedHelmet")) {
    MESSAGE("shared assets not found at " << assets << ": skipped");
    return;
  }
  // Default_metalRoughness.jpg is progressive: its DC scans name AC tables defined only later.
  for (const char* file : {"DamagedHelmet/glTF/Default_albedo.jpg", "DamagedHelmet/glTF/Default_normal.jpg",
                           "DamagedHelmet/glTF/Default_metalRoughness.jpg"}) {
    CAPTURE(file);
    const pbr::ImageRgba8 image = pbr::readPng((assets / file).string());
    CHECK(image.width > 0);
    CHECK(image.pixels.size() == size_t(image.width) * image.height * 4);
  }
}

TEST_CASE("image decode: a PNG whose first data chunk is empty decodes like the same PNG without it") {
  const pbr::ImageRgba8 image{3, 2, {10, 20, 30, 255, 40, 50, 60, 255, 70, 80, 90, 255,
                                     1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12}};
  std::ostringstream encoded;
  pbr::writePng(encoded, image);
  const std::string png = encoded.str();
  // An empty IDAT (length 0, its CRC) before the first real one: legal, and what made stb_image copy into a
  // buffer it had not allocated (undefined behaviour that UBSan reports).
  const size_t idat = png.find("IDAT") - 4;
  const std::string empty("\0\0\0\0IDAT\x35\xaf\x06\x1e", 12);
  const std::string withEmpty = png.substr(0, idat) + empty + png.substr(idat);
  const std::vector<unsigned char> bytes(withEmpty.begin(), withEmpty.end());
  const pbr::ImageRgba8 decoded = pbr::decodeImage(bytes.data(), bytes.size(), "empty-idat.png");
  CHECK(decoded.width == 3);
  CHECK(decoded.height == 2);
  CHECK(decoded.pixels == image.pixels);
}

TEST_CASE("image decode: a header declaring more pixels than the image limit is refused before decoding") {
  // A 2x2 JPEG whose frame header is rewritten to 6432 x 65280: stb_image would allocate 2.5 GB for its component
  // buffers from the header alone (a texture fuzzing find; stb refuses PNGs over 1 GiB by itself).
  std::string jpeg;
  const std::vector<unsigned char> pixels(2 * 2 * 3, 128);
  stbi_write_jpg_to_func([](void* out, void* data, int size) { static_cast<std::string*>(out)->append(
                             static_cast<const char*>(data), size_t(size)); },
                         &jpeg, 2, 2, 3, pixels.data(), 90);
  const size_t sof = jpeg.find("\xff\xc0");
  REQUIRE(sof != std::string::npos);
  const unsigned char size[4] = {0xFF, 0x00, 0x19, 0x20};  // height 65280, width 6432
  jpeg.replace(sof + 5, 4, reinterpret_cast<const char*>(size), 4);
  const std::vector<unsigned char> bytes(jpeg.begin(), jpeg.end());
  CHECK_THROWS_WITH(pbr::decodeImage(bytes.data(), bytes.size(), "bomb.jpg"),
                    "bomb.jpg: cannot decode image: 6432x65280 pixels, over the image limit (16384 a side, "
                    "67108864 pixels in all)");
}

TEST_CASE("image decode: a PNG chunk declaring more bytes than the file holds is refused before stb_image sizes it") {
  // A valid PNG with a second IDAT whose length field says 1.9 GB: stb_image would grow its data buffer to that
  // before finding the bytes missing (a texture fuzzing find: malloc of 2 GiB from a file of a few hundred bytes).
  const pbr::ImageRgba8 image{2, 2, {10, 20, 30, 255, 40, 50, 60, 255, 70, 80, 90, 255, 1, 2, 3, 4}};
  std::ostringstream encoded;
  pbr::writePng(encoded, image);
  std::string png = encoded.str();
  const size_t end = png.find("IEND") - 4;
  const std::string bogus("\x72\x00\x00\xd3IDAT\0\0\0\0", 12);
  png = png.substr(0, end) + bogus + png.substr(end);
  const std::vector<unsigned char> bytes(png.begin(), png.end());
  CHECK_THROWS_WITH(pbr::decodeImage(bytes.data(), bytes.size(), "long.png"),
                    ("long.png: cannot decode image: PNG chunk at byte " + std::to_string(end) +
                     " declares 1912602835 bytes, past the end of the data (" + std::to_string(bytes.size()) +
                     " bytes)").c_str());
}

TEST_CASE("image decode: a lossless WebP decodes to the pixels it encodes, and a cut one is refused with a reason") {
  pbr::ImageRgba8 image{5, 3, {}};
  for (int i = 0; i < 15; ++i) {
    image.pixels.insert(image.pixels.end(), {static_cast<unsigned char>(17 * i), static_cast<unsigned char>(255 - i),
                                             static_cast<unsigned char>(i * i), static_cast<unsigned char>(128 + i)});
  }
  uint8_t* encoded = nullptr;
  const size_t size = WebPEncodeLosslessRGBA(image.pixels.data(), image.width, image.height, image.width * 4, &encoded);
  REQUIRE(size > 0);
  const std::vector<unsigned char> webp(encoded, encoded + size);
  WebPFree(encoded);
  const pbr::ImageRgba8 decoded = pbr::decodeImage(webp.data(), webp.size(), "t.webp");
  CHECK(decoded.width == 5);
  CHECK(decoded.height == 3);
  CHECK(decoded.pixels == image.pixels);
  // The RIFF header kept, the data cut: libwebp finds the image incomplete.
  const std::vector<unsigned char> cut(webp.begin(), webp.begin() + 20);
  CHECK(decodeError(cut) == "t.jpg: cannot decode image: not a valid WebP file");
}

TEST_CASE("image decode: formats other than PNG, JPEG and WebP are refused before stb_image reads them") {
  // A Radiance picture (stb's loader for it loops endlessly on some corrupt files), a BMP and a GIF header.
  const std::string hdr = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 1\n\x80\x80\x80\x81";
  const std::string bmp = std::string("BM") + std::string(52, '\0');
  const std::string gif = "GIF89a" + std::string(20, '\0');
  for (const std::string& bytes : {hdr, bmp, gif}) {
    CAPTURE(bytes.substr(0, 6));
    CHECK(decodeError(std::vector<unsigned char>(bytes.begin(), bytes.end())) ==
          "t.jpg: cannot decode image: not a PNG, JPEG or WebP image");
  }
}
