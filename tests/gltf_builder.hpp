#pragma once
// Small glTF 2.0 files written by tests: a JSON document and one binary buffer, saved as .gltf + .bin or as .glb.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/gtc/type_precision.hpp>
#include <glm/mat2x2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <nlohmann/json.hpp>

#include "core/scene/image.hpp"

namespace pbr::test {

class GltfBuilder {
 public:
  GltfBuilder();  // asset 2.0, one scene (the default) without nodes

  nlohmann::json doc;
  std::vector<unsigned char> bin;

  // A buffer view over `bytes` appended to the buffer (4-byte aligned).
  int addView(const void* data, size_t bytes);
  // FLOAT accessor of `type` ("VEC2", "VEC3", "VEC4") over tightly packed values.
  int addFloats(const std::vector<float>& values, const char* type);
  int addIndices(const std::vector<uint32_t>& indices);  // UNSIGNED_INT SCALAR
  // Writes `image` as PNG `file` into `dir` and adds an image, a sampler-less texture; returns the texture.
  int addPngTexture(const std::filesystem::path& dir, const std::string& file, const ImageRgba8& image);
  int addMaterial(const nlohmann::json& material);
  int addMesh(const nlohmann::json& primitive);
  // A node of the default scene.
  int addRootNode(const nlohmann::json& node);

  // <name>.gltf with <name>.bin beside it; returns the .gltf path.
  std::string writeGltf(const std::filesystem::path& dir, const std::string& name) const;
  // <name>.glb with the buffer as its BIN chunk; images stay external files.
  std::string writeGlb(const std::filesystem::path& dir, const std::string& name) const;
};

// A 2 x 2 square in the z = 0 plane facing +Z, corners (+-1, +-1), counter-clockwise seen from +Z, with
// uv = uvFromXy * (x, y) + (0.5, 0.5). The default maps the image upright: u to the right, v (down the image) to
// -y. With `tangents`, TANGENT holds `tangent` at every vertex. Returns the mesh index.
struct QuadSpec {
  glm::mat2 uvFromXy = glm::mat2(0.5f, 0.0f, 0.0f, -0.5f);
  bool normals = true;
  bool tangents = false;
  glm::vec4 tangent{1.0f, 0.0f, 0.0f, 1.0f};
  int material = -1;
};
int addQuad(GltfBuilder& builder, const QuadSpec& spec);

// A model of one default quad, the default scene's only node.
GltfBuilder quadModel();

// A w x h image of one RGBA colour.
ImageRgba8 solidImage(int w, int h, glm::u8vec4 rgba);

}  // namespace pbr::test
