#pragma once
#include <cstddef>
#include <filesystem>
#include <string>

#include "core/scene/uri_policy.hpp"

namespace pbr {

// The file a glTF buffer or image URI (not a data: URI) names: percent-decoded, resolved against `folder` (the
// .gltf/.glb file's folder) and checked to be a regular file inside that folder unless `policy` allows otherwise.
// Throws std::runtime_error with what is wrong, without the field name, e.g. "'%ZZ.bin': bad percent-encoding",
// "'../../etc/passwd' leaves the model's folder (--allow-outside-uris allows it)", "'.': not a regular file (a
// directory)".
std::filesystem::path resolveGltfUri(const std::string& uri, const std::filesystem::path& folder,
                                     const UriPolicy& policy);
// resolveGltfUri without the check that the file is there: for an image, whose file may be missing (drawn as a
// placeholder, GltfMaterials) where a buffer's may not.
std::filesystem::path placeGltfUri(const std::string& uri, const std::filesystem::path& folder,
                                   const UriPolicy& policy);

bool isDataUri(const std::string& uri);

// The number of bytes a base64 data: URI decodes to, without decoding it; throws std::runtime_error for a data
// URI that is not base64.
std::size_t dataUriSize(const std::string& uri);

// A URI as messages quote it: a data: URI as its header ("data:image/png;base64,..."), any URI cut to 60
// characters.
std::string quoteUri(const std::string& uri);

}  // namespace pbr
