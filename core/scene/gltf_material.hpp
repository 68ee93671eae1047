#pragma once
#include <string>

#include "core/scene/gltf_file.hpp"
#include "core/scene/scene.hpp"

namespace pbr {

// Converts a file's materials, and the textures they use, into pbr::Material and Scene::textures. Each glTF
// texture is decoded once per colour space it is used in (base colour and emissive are sRGB, the others linear).
// What `loaded` already holds, from an earlier load of the file into the scene, is reused; what is converted
// is added to it.
class GltfMaterials {
 public:
  GltfMaterials(const GltfFile& file, Scene& scene, LoadedGltf& loaded) : file_(file), scene_(scene), loaded_(loaded) {}

  // Material `index` (-1: glTF's default material), converted and its images decoded on first use; `field`
  // names the reference for messages.
  const Material& get(int index, const std::string& field);

 private:
  Material convert(int index, const std::string& field);
  // A material extension's map `key` of `extension` (a textureInfo, as the core's), none where absent; `owner`
  // names the extension for messages.
  MaterialMap extensionMap(const tinygltf::Value& extension, const char* key, bool srgb, const std::string& owner);
  // KHR_materials_ior and KHR_materials_specular's factors and maps into `m`.
  void readSpecular(const tinygltf::Material& g, const std::string& name, Material& m);
  // KHR_materials_clearcoat's factors and maps into `m`.
  void readClearcoat(const tinygltf::Material& g, const std::string& name, Material& m);
  // KHR_materials_sheen's factors and maps into `m`.
  void readSheen(const tinygltf::Material& g, const std::string& name, Material& m);
  // KHR_materials_transmission and KHR_materials_volume's factors and maps into `m`.
  void readTransmission(const tinygltf::Material& g, const std::string& name, Material& m);
  // KHR_materials_pbrSpecularGlossiness into `m` by KHR_materials_specular's conversion; false without it.
  bool readSpecularGlossiness(const tinygltf::Material& g, const std::string& name, Material& m);
  // Index into Scene::textures of glTF texture `index`.
  int texture(int index, bool srgb, const std::string& field);
  // Decodes image `image` into `data`'s pixels and name; false, with `problem` saying why, where its file is
  // missing or unreadable or its bytes are no image stb decodes (one message per image, however many use it).
  bool readImage(int image, TextureData& data, std::string& problem) const;

  const GltfFile& file_;
  Scene& scene_;
  LoadedGltf& loaded_;
};

}  // namespace pbr
