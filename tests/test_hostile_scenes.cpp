// Hostile scene files and glTF models: each is refused by `pbr render` with exit code 1 and one short line naming
// the file and the field, and no frame is written.
#include <doctest/doctest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "tests/cli_util.hpp"
#include "tests/gltf_builder.hpp"
#include "tests/refusal_checks.hpp"

using pbr::test::checkRefused;
using pbr::test::GltfBuilder;
using pbr::test::quadModel;
using pbr::test::TempDir;

namespace {

const std::string kCamera = R"("camera": {"position": [0, 2, 6], "target": [0, 0, 0]})";

std::string nested(int depth) { return std::string(static_cast<size_t>(depth), '[') + std::string(static_cast<size_t>(depth), ']'); }

// A PNG whose zlib stream is corrupt: stb refuses it without setting a failure reason.
std::string corruptPng() {
  const std::string sig = "\x89PNG\r\n\x1a\n";
  // IHDR of a 2 x 2 RGBA image (CRC included) and an IDAT of 6 bytes with a valid CRC.
  const unsigned char ihdr[] = {0, 0, 0, 13, 'I', 'H', 'D', 'R', 0, 0, 0, 2, 0, 0, 0, 2, 8, 6, 0, 0, 0, 0x72, 0xb6, 0x0d, 0x24};
  const unsigned char idat[] = {0, 0, 0, 6, 'I', 'D', 'A', 'T', 0x78, 0x9c, 0xff, 0xff, 0xff, 0xff, 0x8b, 0x2b, 0x76, 0x8e};
  return sig + std::string(reinterpret_cast<const char*>(ihdr), sizeof ihdr) +
         std::string(reinterpret_cast<const char*>(idat), sizeof idat);
}

}  // namespace

TEST_CASE("hostile scenes: JSON nested far past the limit is refused before parsing, with its position") {
  const TempDir dir;
  const std::string deep = dir.write("deep.json", "{" + kCamera + R"(, "extra": )" + nested(100000) + "}");
  checkRefused(dir, deep, {"deep.json:1:", "nesting deeper than 256"});
  // Brackets inside strings are text, not nesting.
  const std::string text = dir.write("text.json", "{" + kCamera + R"(, "exposure": ")" + nested(1000) + R"("})");
  checkRefused(dir, text, {"exposure: expected a number in [0, 1e+06], got \"[[[["});
}

TEST_CASE("hostile scenes: a huge value is quoted by a short prefix") {
  const TempDir dir;
  std::string big = "[0";
  for (int i = 0; i < 200000; ++i) big += ",1";
  const std::string scene = dir.write("big.json", "{" + kCamera + R"(, "exposure": )" + big + "]}");
  checkRefused(dir, scene, {"exposure: expected a number in [0, 1e+06], got [0,1,1,", "..."});
  const std::string deep = dir.write("deep_value.json", "{" + kCamera + R"(, "exposure": )" + nested(250) + "}");
  checkRefused(dir, deep, {"exposure: expected a number in [0, 1e+06], got [[[["});
}

TEST_CASE("hostile scenes: glTF extras nested far past the limit are refused before tinygltf reads them") {
  const TempDir dir;
  const std::string path = quadModel().writeGltf(dir.path(), "deep");
  std::string text = pbr::test::readFile(path);
  text.insert(1, R"("extras": )" + nested(50000) + ",");
  std::ofstream(path, std::ios::binary) << text;
  checkRefused(dir, path, {"deep.gltf:1:", "nesting deeper than 256"});
}

TEST_CASE("hostile scenes: a corrupt PNG the decoder gives no reason for is refused as a JSON texture, as a glTF image with --strict") {
  const TempDir dir;
  dir.write("bad.png", corruptPng());
  const std::string scene = dir.write(
      "textured.json",
      "{" + kCamera + R"(, "objects": [{"shape": "sphere", "material": {"base_color_texture": "bad.png"}}]})");
  checkRefused(dir, scene, {"objects[0].material.base_color_texture", "bad.png: cannot decode image"});

  GltfBuilder b;
  pbr::test::QuadSpec spec;
  spec.material = b.addMaterial({{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}});
  b.doc["images"] = {{{"uri", "bad.png"}}};
  b.doc["textures"] = {{{"source", 0}}};
  b.addRootNode({{"mesh", pbr::test::addQuad(b, spec)}});
  // By default a glTF image is drawn as a placeholder, as viewers do (tests/test_gltf_render.cpp).
  checkRefused(dir, b.writeGltf(dir.path(), "textured"), {"images[0]", "bad.png", "cannot decode image"},
               {"--strict"});
}

TEST_CASE("hostile scenes: every invalid accessor byteOffset names accessors[0].byteOffset") {
  const TempDir dir;
  const std::vector<std::pair<nlohmann::json, std::string>> cases = {
      {-4, "must be a non-negative integer (got -4)"},
      {4.5, "must be a non-negative integer (got 4.5)"},
      {4.0, "must be a non-negative integer (got 4.0)"},
      {"4", "must be a non-negative integer (got \"4\")"},
      {2, "must be a multiple of 4, its component size (got 2)"},
      {4096, "4096 is past the end of bufferViews[0]"},
      {std::uint64_t(1) << 40, "must be an integer in [0, 2147483648]"},
  };
  int n = 0;
  for (const auto& [offset, message] : cases) {
    GltfBuilder b = quadModel();
    b.doc["accessors"][0]["byteOffset"] = offset;
    checkRefused(dir, b.writeGltf(dir.path(), "offset" + std::to_string(n++)), {"accessors[0].byteOffset: " + message});
  }
  GltfBuilder b = quadModel();
  b.doc["accessors"][0]["count"] = 1000;
  checkRefused(dir, b.writeGltf(dir.path(), "count"), {"accessors[0].count: 1000 elements", "past the end of bufferViews[0]"});
}

TEST_CASE("hostile scenes: buffer and image URIs that are directories, badly encoded or the wrong size") {
  const TempDir dir;
  int n = 0;
  for (const std::string uri : {".", "%ZZ.bin", "%00.bin", "sub", ""}) {
    std::filesystem::create_directories(dir.path() / "sub");
    GltfBuilder b = quadModel();
    const std::string path = b.writeGltf(dir.path(), "uri" + std::to_string(n++));
    std::string text = pbr::test::readFile(path);
    nlohmann::json doc = nlohmann::json::parse(text);
    doc["buffers"][0]["uri"] = uri;
    std::ofstream(path) << doc.dump();
    CAPTURE(uri);
    checkRefused(dir, path, {"buffers[0].uri: "});
  }
  GltfBuilder image = quadModel();
  image.doc["images"] = {{{"uri", "."}}};
  checkRefused(dir, image.writeGltf(dir.path(), "image_dir"), {"images[0].uri: '.': not a regular file (a directory)"},
               {"--strict"});

  GltfBuilder longer = quadModel();
  const std::string path = longer.writeGltf(dir.path(), "length");
  nlohmann::json doc = nlohmann::json::parse(pbr::test::readFile(path));
  const size_t size = doc["buffers"][0]["byteLength"].get<size_t>();
  doc["buffers"][0]["byteLength"] = size + 4;
  std::ofstream(path) << doc.dump();
  checkRefused(dir, path, {"buffers[0].byteLength: " + std::to_string(size + 4) + ", but 'length.bin' holds " + std::to_string(size) + " bytes"});

  // A data: URI of the wrong length is reported without its payload.
  doc["buffers"][0]["byteLength"] = 30003;
  doc["buffers"][0]["uri"] = "data:application/octet-stream;base64," + std::string(40000, 'A');
  std::ofstream(path) << doc.dump();
  checkRefused(dir, path, {"buffers[0].byteLength: 30003, but 'data:application/octet-stream;base64,...' holds 30000"});
}

TEST_CASE("hostile scenes: a GLB with a damaged header says which part is wrong") {
  const TempDir dir;
  const std::string path = quadModel().writeGlb(dir.path(), "model");
  const std::string good = pbr::test::readFile(path);
  const auto damaged = [&](size_t at, const std::string& bytes, const std::string& name) {
    std::string text = good;
    text.replace(at, bytes.size(), bytes);
    std::ofstream(dir.file(name), std::ios::binary) << text;
    return dir.file(name);
  };
  checkRefused(dir, damaged(0, "glTX", "magic.glb"), {"GLB header: magic is \"glTX\", expected \"glTF\""});
  checkRefused(dir, damaged(4, std::string("\x03\0\0\0", 4), "version.glb"), {"GLB header: version is 3, expected 2"});
  checkRefused(dir, damaged(8, std::string("\x01\0\0\0", 4), "length.glb"), {"GLB header: length is 1, but the file has"});
  checkRefused(dir, damaged(16, "JSOX", "chunk.glb"), {"GLB chunk 0: type is \"JSOX\", expected \"JSON\""});
  checkRefused(dir, damaged(12, std::string("\xff\xff\0\0", 4), "chunk_length.glb"), {"GLB chunk 0: length 65535 runs past the end"});
}

TEST_CASE("hostile scenes: degenerate and overflowing node transforms are reported against the node") {
  const TempDir dir;
  const std::vector<std::pair<nlohmann::json, std::string>> cases = {
      {{{"scale", {0, 1, 1}}}, "nodes[0].scale: [0, 1, 1] is zero or nearly so"},
      {{{"scale", {1e-20, 1e-20, 1}}}, "nodes[0].scale: "},
      {{{"matrix", std::vector<double>(16, 0.0)}}, "nodes[0].matrix: its last row must be (0, 0, 0, 1)"},
      {{{"matrix", {1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}}}, "nodes[0].matrix: is singular"},
      {{{"translation", {1e30, 0, 0}}}, "nodes[0].translation: 1e+30 is beyond the coordinate limit 1e+12"},
      {{{"translation", {"x", 0, 0}}}, "nodes[0].translation: must be an array of 3 numbers"},
  };
  int n = 0;
  for (const auto& [transform, message] : cases) {
    GltfBuilder b = quadModel();
    for (const auto& [key, value] : transform.items()) b.doc["nodes"][0][key] = value;
    checkRefused(dir, b.writeGltf(dir.path(), "node" + std::to_string(n++)), {message});
  }
  // Each finite, together past the limit: the child that goes over is named.
  GltfBuilder b = quadModel();
  b.doc["nodes"][0]["translation"] = {9e11, 0, 0};
  b.doc["nodes"].push_back({{"translation", {9e11, 0, 0}}, {"mesh", 0}});
  b.doc["nodes"][0]["children"] = {1};
  checkRefused(dir, b.writeGltf(dir.path(), "sum"), {"nodes[1].translation: with its parents' transforms, places the node at 1.8e+12"});
  // A light brighter than float range names its intensity, not the luminous_power it becomes.
  GltfBuilder light = quadModel();
  light.doc["extensions"]["KHR_lights_punctual"]["lights"] = {{{"type", "point"}, {"intensity", 1e38}}};
  light.doc["extensionsUsed"] = {"KHR_lights_punctual"};
  light.doc["nodes"][0]["extensions"]["KHR_lights_punctual"]["light"] = 0;
  checkRefused(dir, light.writeGltf(dir.path(), "light"), {"lights[0].intensity: too large"});
}

TEST_CASE("hostile scenes: JSON positions, scales and radii beyond the coordinate limit name their field") {
  const TempDir dir;
  const std::string object = R"("objects": [{"shape": "sphere", "transform": )";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {object + R"({"translate": [1e30, 0, 0]}}])", "objects[0].transform.translate[0]: expected a number in [-1e+12, 1e+12], got 1e+30"},
      {object + R"({"scale": 1e-20}}])", "objects[0].transform.scale: expected a number in [1e-09, 1e+12], got 1e-20"},
      {object + R"({"scale": [1, 1e13, 1]}}])", "objects[0].transform.scale[1]: expected a number in [1e-09, 1e+12]"},
      {R"("lights": [{"position": [0, -2e12, 0], "radius": 1, "luminous_power": 1}])", "lights[0].position[1]: expected a number in [-1e+12, 1e+12]"},
      {R"("lights": [{"position": [0, 0, 0], "radius": 1e20, "luminous_power": 1}])", "lights[0].radius: expected a number in [0, 1e+12], got 1e+20"},
  };
  int n = 0;
  for (const auto& [body, message] : cases) {
    checkRefused(dir, dir.write("far" + std::to_string(n++) + ".json", "{" + kCamera + ", " + body + "}"), {message});
  }
  const std::string camera = dir.write("camera.json", R"({"camera": {"position": [0, 0, 3e12], "target": [0, 0, 0]}})");
  checkRefused(dir, camera, {"camera.position[2]: expected a number in [-1e+12, 1e+12], got 3000000000000.0"});
}
