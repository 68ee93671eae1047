#pragma once
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/scene/gltf_file.hpp"

namespace pbr {

// A primitive's KHR_draco_mesh_compression data decoded by Draco (Debian's libdraco-dev): each compressed attribute
// as floats, as many components an element as its accessor's type has (normalized integers mapped to [0, 1] or
// [-1, 1]), by glTF attribute name; the triangles' indices into them.
struct DracoPrimitive {
  std::map<std::string, std::vector<float>> attributes;
  std::vector<uint32_t> indices;
  size_t vertices = 0;
};

// The decoded primitive, or nothing where it has no KHR_draco_mesh_compression extension. Throws SceneError naming
// `field` (the primitive) and the extension's field for a bad bufferView or attribute id, and Draco's own message
// for data it cannot decode; a decoded mesh's indices are checked against its vertex count.
std::optional<DracoPrimitive> decodeDracoPrimitive(const GltfFile& file, const tinygltf::Primitive& primitive,
                                                   const std::string& field);

}  // namespace pbr
