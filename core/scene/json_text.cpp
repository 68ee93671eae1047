#include "core/scene/json_text.hpp"

#include <algorithm>

#include "core/scene/scene.hpp"

namespace pbr {

namespace {

// Appends `value` to `out` until `out` holds `limit` characters. The recursion is as deep as the value's nesting,
// which checkJsonNesting bounds; every level also adds a character, so it ends once the limit is reached.
void appendPrefix(const nlohmann::json& value, std::size_t limit, std::string& out) {
  if (out.size() >= limit) return;
  if (value.is_string()) {
    const std::string& s = value.get_ref<const std::string&>();
    // Quote no more of the string than can show; dump() escapes it as the file would spell it.
    out += jsonText(nlohmann::json(s.substr(0, limit - out.size() + 1)));
    return;
  }
  if (!value.is_structured()) {
    out += jsonText(value);
    return;
  }
  const bool object = value.is_object();
  out += object ? '{' : '[';
  bool first = true;
  for (auto it = value.begin(); it != value.end() && out.size() < limit; ++it) {
    if (!first) out += ',';
    first = false;
    if (object) out += jsonText(nlohmann::json(it.key())) + ":";
    appendPrefix(it.value(), limit, out);
  }
  out += object ? '}' : ']';
}

}  // namespace

std::string jsonText(const nlohmann::json& value, int indent) {
  return value.dump(indent, ' ', false, nlohmann::json::error_handler_t::replace);
}

std::string lineColumn(const std::string& text, std::size_t offset) {
  const std::size_t end = std::min(offset, text.size());
  std::size_t line = 1, lineStart = 0;
  for (std::size_t i = 0; i < end; ++i) {
    if (text[i] == '\n') {
      ++line;
      lineStart = i + 1;
    }
  }
  return std::to_string(line) + ":" + std::to_string(end - lineStart + 1);
}

void checkJsonNesting(const std::string& text, const std::string& file) {
  int depth = 0;
  bool inString = false, escaped = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (inString) {
      if (escaped) {
        escaped = false;
      } else if (c == '\\') {
        escaped = true;
      } else if (c == '"') {
        inString = false;
      }
    } else if (c == '"') {
      inString = true;
    } else if (c == '[' || c == '{') {
      if (++depth > kMaxJsonNesting) {
        throw SceneError(file + ":" + lineColumn(text, i) + ": nesting deeper than " + std::to_string(kMaxJsonNesting));
      }
    } else if (c == ']' || c == '}') {
      // Unbalanced closers are the parser's to report.
      depth = std::max(depth - 1, 0);
    }
  }
}

std::string quoteJson(const nlohmann::json& value, std::size_t maxChars) {
  std::string out;
  appendPrefix(value, maxChars, out);
  return out.size() <= maxChars ? out : out.substr(0, maxChars - 3) + "...";
}

}  // namespace pbr
