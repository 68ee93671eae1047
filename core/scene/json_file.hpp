#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace pbr {

// Reads (through readInputFile) and parses a JSON file. Throws SceneError with one line: "F: not a regular file
// (a directory)", "F:LINE:COLUMN: nesting deeper than 256", "F:LINE:COLUMN: JSON syntax error: ..." (a number
// out of range also names its JSON path), or "F: lights: given twice in one object (...)" for a duplicate key.
nlohmann::json readJsonFile(const std::string& path);

// Parses JSON text read from `path` (a glTF file or a GLB's JSON chunk) with the checks and messages of
// readJsonFile; with `duplicates`, a key given twice in one object is not refused but its path noted there, the
// later value kept (as JSON.parse, and so the viewers, read it).
nlohmann::json parseJsonText(const std::string& text, const std::string& path,
                             std::vector<std::string>* duplicates = nullptr);

}  // namespace pbr
