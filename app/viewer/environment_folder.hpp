#pragma once
#include <optional>
#include <string>
#include <vector>

#include "core/scene/scene.hpp"

namespace pbr {

// The folder the overlay's environment picker lists: `chosen` (--env-dir) when given, else the folder of the
// scene's .hdr, else the shared asset folder's environments/.
std::string environmentFolder(const std::string& chosen, const std::optional<EnvironmentDesc>& current);

// The environment pictures (Radiance .hdr and OpenEXR .exr, any case) directly in `folder`, as paths, sorted; none
// when it cannot be read.
std::vector<std::string> hdrFiles(const std::string& folder);

}  // namespace pbr
