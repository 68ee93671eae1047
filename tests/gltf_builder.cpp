#include "tests/gltf_builder.hpp"

#include <algorithm>
#include <cstring>
#include <fstream>

#include "core/io/image_output.hpp"

namespace pbr::test {

namespace fs = std::filesystem;
using nlohmann::json;

GltfBuilder::GltfBuilder() {
  doc = {{"asset", {{"version", "2.0"}}},
         {"scene", 0},
         {"scenes", json::array({json::object({{"nodes", json::array()}})})}};
}

int GltfBuilder::addView(const void* data, size_t bytes) {
  while (bin.size() % 4) bin.push_back(0);
  const size_t offset = bin.size();
  bin.resize(offset + bytes);
  std::memcpy(bin.data() + offset, data, bytes);
  doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", bytes}});
  return static_cast<int>(doc["bufferViews"].size()) - 1;
}

int GltfBuilder::addFloats(const std::vector<float>& values, const char* type) {
  const size_t components = std::string(type) == "VEC2" ? 2 : std::string(type) == "VEC3" ? 3 : 4;
  const int view = addView(values.data(), values.size() * sizeof(float));
  json accessor = {
      {"bufferView", view}, {"componentType", 5126}, {"count", values.size() / components}, {"type", type}};
  if (components == 3) {
    // POSITION accessors must state their bounds.
    json lo = json::array(), hi = json::array();
    for (size_t c = 0; c < 3; ++c) {
      float mn = values[c], mx = values[c];
      for (size_t i = c; i < values.size(); i += 3) {
        mn = std::min(mn, values[i]);
        mx = std::max(mx, values[i]);
      }
      lo.push_back(mn);
      hi.push_back(mx);
    }
    accessor["min"] = lo;
    accessor["max"] = hi;
  }
  doc["accessors"].push_back(accessor);
  return static_cast<int>(doc["accessors"].size()) - 1;
}

int GltfBuilder::addIndices(const std::vector<uint32_t>& indices) {
  const int view = addView(indices.data(), indices.size() * sizeof(uint32_t));
  doc["accessors"].push_back(
      {{"bufferView", view}, {"componentType", 5125}, {"count", indices.size()}, {"type", "SCALAR"}});
  return static_cast<int>(doc["accessors"].size()) - 1;
}

int GltfBuilder::addPngTexture(const fs::path& dir, const std::string& file, const ImageRgba8& image) {
  writePng((dir / file).string(), image);
  doc["images"].push_back({{"uri", file}});
  doc["textures"].push_back({{"source", doc["images"].size() - 1}});
  return static_cast<int>(doc["textures"].size()) - 1;
}

int GltfBuilder::addMaterial(const json& material) {
  doc["materials"].push_back(material);
  return static_cast<int>(doc["materials"].size()) - 1;
}

int GltfBuilder::addMesh(const json& primitive) {
  doc["meshes"].push_back({{"primitives", json::array({primitive})}});
  return static_cast<int>(doc["meshes"].size()) - 1;
}

int GltfBuilder::addRootNode(const json& node) {
  doc["nodes"].push_back(node);
  const int index = static_cast<int>(doc["nodes"].size()) - 1;
  doc["scenes"][0]["nodes"].push_back(index);
  return index;
}

std::string GltfBuilder::writeGltf(const fs::path& dir, const std::string& name) const {
  json out = doc;
  if (!bin.empty()) {
    // The binary is buffer 0; buffers a test adds after it are kept.
    const json first = {{"byteLength", bin.size()}, {"uri", name + ".bin"}};
    if (out.contains("buffers") && !out["buffers"].empty()) {
      out["buffers"][0] = first;
    } else {
      out["buffers"] = json::array({first});
    }
    std::ofstream(dir / (name + ".bin"), std::ios::binary)
        .write(reinterpret_cast<const char*>(bin.data()), static_cast<std::streamsize>(bin.size()));
  }
  const fs::path path = dir / (name + ".gltf");
  std::ofstream(path) << out.dump(1);
  return path.string();
}

std::string GltfBuilder::writeGlb(const fs::path& dir, const std::string& name) const {
  json out = doc;
  if (!bin.empty() && out.contains("buffers") && !out["buffers"].empty()) {
    out["buffers"][0] = {{"byteLength", bin.size()}};
  } else if (!bin.empty()) {
    out["buffers"] = json::array({{{"byteLength", bin.size()}}});
  }
  std::string text = out.dump();
  while (text.size() % 4) text.push_back(' ');  // chunks are 4-byte aligned, JSON padded with spaces
  std::vector<unsigned char> payload = bin;
  while (payload.size() % 4) payload.push_back(0);
  std::vector<unsigned char> glb;
  const auto word = [&](uint32_t v) {
    for (int i = 0; i < 4; ++i) glb.push_back(static_cast<unsigned char>(v >> (8 * i)));
  };
  word(0x46546C67u);  // "glTF"
  word(2u);
  word(static_cast<uint32_t>(12 + 8 + text.size() + (payload.empty() ? 0 : 8 + payload.size())));
  word(static_cast<uint32_t>(text.size()));
  word(0x4E4F534Au);  // "JSON"
  glb.insert(glb.end(), text.begin(), text.end());
  if (!payload.empty()) {
    word(static_cast<uint32_t>(payload.size()));
    word(0x004E4942u);  // "BIN\0"
    glb.insert(glb.end(), payload.begin(), payload.end());
  }
  const fs::path path = dir / (name + ".glb");
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(glb.data()), static_cast<std::streamsize>(glb.size()));
  return path.string();
}

int addQuad(GltfBuilder& builder, const QuadSpec& spec) {
  const float corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  std::vector<float> positions, normals, uvs, tangents;
  for (const auto& c : corners) {
    positions.insert(positions.end(), {c[0], c[1], 0.0f});
    normals.insert(normals.end(), {0.0f, 0.0f, 1.0f});
    const glm::vec2 uv = spec.uvFromXy * glm::vec2(c[0], c[1]) + glm::vec2(0.5f);
    uvs.insert(uvs.end(), {uv.x, uv.y});
    tangents.insert(tangents.end(), {spec.tangent.x, spec.tangent.y, spec.tangent.z, spec.tangent.w});
  }
  json attributes = {{"POSITION", builder.addFloats(positions, "VEC3")},
                     {"TEXCOORD_0", builder.addFloats(uvs, "VEC2")}};
  if (spec.normals) attributes["NORMAL"] = builder.addFloats(normals, "VEC3");
  if (spec.tangents) attributes["TANGENT"] = builder.addFloats(tangents, "VEC4");
  json primitive = {{"attributes", attributes}, {"indices", builder.addIndices({0, 1, 2, 0, 2, 3})}};
  if (spec.material >= 0) primitive["material"] = spec.material;
  return builder.addMesh(primitive);
}

GltfBuilder quadModel() {
  GltfBuilder b;
  b.addRootNode({{"mesh", addQuad(b, {})}});
  return b;
}

ImageRgba8 solidImage(int w, int h, glm::u8vec4 rgba) {
  ImageRgba8 image{w, h, {}};
  for (int i = 0; i < w * h; ++i) image.pixels.insert(image.pixels.end(), {rgba.x, rgba.y, rgba.z, rgba.w});
  return image;
}

}  // namespace pbr::test
