#pragma once
#include <string>

namespace pbr {

// A file name's extension in lower case with its dot (".exr"), or "": formats are chosen by it, case-insensitively.
std::string lowerExtension(const std::string& path);

}  // namespace pbr
