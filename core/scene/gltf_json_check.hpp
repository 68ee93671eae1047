#pragma once
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "core/scene/uri_policy.hpp"

namespace pbr {

// What checkGltfJson needs beyond the document.
struct GltfJsonContext {
  std::string path;                   // the .gltf/.glb file, as messages name it
  std::filesystem::path folder;       // URIs resolve against it
  UriPolicy policy;
  std::optional<std::size_t> binChunk;  // a GLB's BIN chunk length
};

// Checks a glTF document as written, before tinygltf reads it: tinygltf turns a fractional or string index into 0,
// -1 or "absent" without a word, so each integer the specification constrains is checked here from the JSON: a
// non-negative integer of the allowed values, an index in range of its array, accessor offsets aligned to their
// component size and accessors and buffer views within their buffer views and buffers. Node transforms and the
// KHR_texture_transform of each textureInfo must be numbers, in arrays of the right length. Buffer and image URIs are resolved (resolveGltfUri) and buffer lengths
// compared with the data. Throws SceneError("PATH: accessors[3].byteOffset: must be a non-negative integer (got
// -4)").
void checkGltfJson(const nlohmann::json& doc, const GltfJsonContext& context);

// EXT_meshopt_compression: a buffer marked as the fallback of compressed views, which may hold no data (no URI),
// as gltfpack writes it; its views are then decoded from compressed ones (gltf_meshopt.hpp).
bool isMeshoptFallback(const nlohmann::json& buffer);

}  // namespace pbr
