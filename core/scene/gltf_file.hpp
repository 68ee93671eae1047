#pragma once
#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "core/scene/uri_policy.hpp"

namespace pbr {

// A parsed glTF file. tinygltf decodes no image: external and data-URI images keep their encoded bytes in
// `encodedImages`, decoded later and only when a material uses them; images stored in buffer views are read from
// the view once it has been validated (tinygltf does not check its bounds).
struct GltfFile {
  std::string path;  // as given; every message starts with it
  tinygltf::Model model;
  std::vector<std::vector<unsigned char>> encodedImages;  // by image index; empty for buffer-view images
  std::vector<std::string> imageMimeTypes;  // by image index, as written ("" for none): tinygltf keeps only some
  UriPolicy policy;                                       // as read: where files may be, and --strict

  // Throws SceneError("<path>: <what>").
  [[noreturn]] void fail(const std::string& what) const;
  // One line "<path>: <what>" on stderr (warnOnce: once per process), for what is drawn differently from the
  // file's intent.
  void warn(const std::string& what) const;
};

// "array[index]", how messages name an element of a top-level glTF array.
inline std::string gltfElement(const char* array, int index) {
  return std::string(array) + "[" + std::to_string(index) + "]";
}

// Extensions this loader implements; a file that requires any other is rejected, one that uses any other is read
// without it and says so in one line.
inline const char* const kSupportedGltfExtensions[] = {"KHR_lights_punctual", "KHR_materials_emissive_strength",
                                                       "KHR_materials_unlit", "KHR_mesh_quantization",
                                                       "KHR_texture_transform", "EXT_mesh_gpu_instancing",
                                                       "EXT_texture_webp", "KHR_draco_mesh_compression",
                                                       "EXT_meshopt_compression", "KHR_materials_ior",
                                                       "KHR_materials_specular",
                                                       "KHR_materials_pbrSpecularGlossiness",
                                                       "KHR_materials_clearcoat", "KHR_materials_sheen",
                                                       "KHR_materials_transmission", "KHR_materials_volume"};

// Reads a .gltf or .glb file (a .glb by its extension or the GLB magic) with its buffers, every file through
// readInputFile. Before tinygltf sees the file, the GLB container is checked (readGlbChunks), the JSON's nesting
// bounded (checkJsonNesting) and its integers, offsets and URIs validated (checkGltfJson); URIs must stay in the
// model's folder unless `policy` allows otherwise.
GltfFile readGltfFile(const std::string& path, const UriPolicy& policy = {});

}  // namespace pbr
