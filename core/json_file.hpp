#pragma once
#include <string>

#include <nlohmann/json.hpp>

namespace pbr {

// Reads (through readInputFile) and parses a JSON file. Throws SceneError with one line: "F: not a regular file
// (a directory)", "F:LINE:COLUMN: nesting deeper than 256", or "F:LINE:COLUMN: JSON syntax error: ..." (a number
// out of range also names its JSON path).
nlohmann::json readJsonFile(const std::string& path);

// Parses JSON text read from `path` (a glTF file or a GLB's JSON chunk) with the checks and messages of
// readJsonFile.
nlohmann::json parseJsonText(const std::string& text, const std::string& path);

}  // namespace pbr
