#pragma once
#include <cstddef>
#include <string>

#include <nlohmann/json.hpp>

namespace pbr {

// Every JSON document the renderer reads (scene files, glTF) is scanned with checkJsonNesting before any parser sees
// it: nlohmann, tinygltf and the code that walks the parsed tree all recurse once per level, so a small file nested
// tens of thousands of levels deep would overflow the stack. Real scenes and models nest a dozen levels or so.
constexpr int kMaxJsonNesting = 256;

// Throws SceneError("FILE:LINE:COLUMN: nesting deeper than 256") at the first bracket past the limit; brackets
// inside strings do not count.
void checkJsonNesting(const std::string& text, const std::string& file);

// "LINE:COLUMN" (both from 1) of the byte at `offset`.
std::string lineColumn(const std::string& text, std::size_t offset);

// The value as JSON text, `indent` as nlohmann's dump. Bytes that are not UTF-8 (a path on a Linux file system, a
// string cut inside a multi-byte character) become U+FFFD instead of throwing, as nlohmann's dump would.
std::string jsonText(const nlohmann::json& value, int indent = -1);

// The value as JSON text, cut to at most about `maxChars` characters ("..." marks a cut) without serialising more
// of it than that: a message quotes a value, never a whole subtree or a megabyte string.
std::string quoteJson(const nlohmann::json& value, std::size_t maxChars = 60);

}  // namespace pbr
