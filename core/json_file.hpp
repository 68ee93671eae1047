#pragma once
#include <string>

#include <nlohmann/json.hpp>

namespace pbr {

// Reads and parses a JSON file. Throws SceneError with one line: "F: cannot open file", or
// "F:LINE:COLUMN: JSON syntax error: ..." (a number out of range also names its JSON path).
nlohmann::json readJsonFile(const std::string& path);

}  // namespace pbr
