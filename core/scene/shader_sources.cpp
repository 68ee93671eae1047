#include "core/scene/shader_sources.hpp"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <regex>
#include <sstream>

namespace pbr {

std::string definesKey(const ShaderDefines& defines) {
  std::string key;
  for (const ShaderDefine& d : defines) key += d.name + '=' + d.value + '\n';
  return key;
}

std::string programLabel(const std::string& files, const ShaderDefines& defines) {
  std::string chosen;
  for (const ShaderDefine& d : defines) {
    if (d.binding || d.value == "0") continue;
    chosen += (chosen.empty() ? "" : " ") + (d.value == "1" ? d.name : d.name + '=' + d.value);
  }
  return chosen.empty() ? files : files + " [" + chosen + "]";
}

namespace fs = std::filesystem;

namespace {

// Mesa reports many errors in included code with source string 0, whatever `#line` set, but keeps the line
// number: so every file's lines are also numbered from its own base, index << kFileLineShift.
constexpr unsigned kFileLineShift = 20;

std::string lineDirective(int line, int index) {
  return "#line " + std::to_string((static_cast<long long>(index) << kFileLineShift) + line) + " " +
         std::to_string(index) + "\n";
}

std::string readFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ShaderError(path.string() + ": cannot open shader file");
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

class Expander {
 public:
  Expander(const fs::path& root, ExpandedShader& out) : root_(root), out_(out) {}

  void root(const std::string& displayName, const fs::path& dir, const std::string& text,
            const ShaderDefines& defines) {
    std::istringstream in(text);
    std::string first;
    std::getline(in, first);
    if (first.rfind("#version", 0) != 0) throw ShaderError(displayName + ":1: the first line must be #version");
    out_.text += first + "\n";
    for (const ShaderDefine& d : defines) out_.text += "#define " + d.name + " " + d.value + "\n";
    const int index = addFile(displayName);
    out_.text += lineDirective(2, index);
    body(in, dir, index, 2);
  }

 private:
  int addFile(const std::string& name) {
    out_.files.push_back(name);
    return static_cast<int>(out_.files.size()) - 1;
  }

  std::string display(const fs::path& path) const {
    const fs::path rel = path.lexically_relative(root_);
    return (root_.filename() / rel).generic_string();
  }

  void body(std::istream& in, const fs::path& dir, int index, int firstLine) {
    static const std::regex includeRe(R"(^\s*#\s*include\s+"([^"]+)\"\s*(//.*)?$)");
    std::string line;
    int lineNo = firstLine;
    for (; std::getline(in, line); ++lineNo) {
      std::smatch m;
      if (!std::regex_match(line, m, includeRe)) {
        out_.text += line + "\n";
        continue;
      }
      fs::path target = (dir / m[1].str()).lexically_normal();
      if (!fs::exists(target)) target = (root_ / m[1].str()).lexically_normal();
      if (!fs::exists(target)) {
        throw ShaderError(out_.files[static_cast<size_t>(index)] + ":" + std::to_string(lineNo) +
                          ": cannot find included file \"" + m[1].str() + "\"");
      }
      const std::string key = fs::weakly_canonical(target).string();
      if (std::find(stack_.begin(), stack_.end(), key) != stack_.end()) {
        throw ShaderError(out_.files[static_cast<size_t>(index)] + ":" + std::to_string(lineNo) +
                          ": \"" + m[1].str() + "\" includes itself");
      }
      // A guard per file instead of skipping repeats here: the expander does not evaluate #if, so only the
      // preprocessor can tell which of two conditional includes of the same file comes first.
      const std::string guard = "PBR_INCLUDED_" + std::to_string(std::hash<std::string>{}(key));
      const int child = addFile(display(target));
      out_.text += "#ifndef " + guard + "\n#define " + guard + "\n" + lineDirective(1, child);
      stack_.push_back(key);
      std::istringstream childIn(readFile(target));
      body(childIn, target.parent_path(), child, 1);
      stack_.pop_back();
      out_.text += "#endif\n";
      out_.text += lineDirective(lineNo + 1, index);
    }
  }

  fs::path root_;
  ExpandedShader& out_;
  std::vector<std::string> stack_;
};

}  // namespace

fs::path ShaderSources::defaultRoot() {
  if (const char* env = std::getenv("PBR_SHADER_DIR"); env && *env) return fs::path(env);
  return fs::path(PBR_SHADER_DIR);
}

ShaderSources::ShaderSources(fs::path root) : root_(fs::absolute(std::move(root)).lexically_normal()) {
  if (!root_.has_filename()) root_ = root_.parent_path();
}

ExpandedShader ShaderSources::expand(const std::string& file, const ShaderDefines& defines) const {
  const fs::path path = (root_ / file).lexically_normal();
  ExpandedShader out;
  Expander(root_, out).root((root_.filename() / file).generic_string(), path.parent_path(), readFile(path), defines);
  return out;
}

ExpandedShader ShaderSources::expandSource(const std::string& name, const std::string& text,
                                           const ShaderDefines& defines) const {
  ExpandedShader out;
  Expander(root_, out).root(name, root_, text, defines);
  return out;
}

std::string remapShaderLog(const std::string& log, const std::vector<std::string>& files) {
  static const std::regex mesaRe(R"(^\s*(\d+):(\d+)\(\d+\):\s*(.*)$)");
  static const std::regex nvidiaRe(R"(^\s*(\d+)\((\d+)\)\s*:\s*(.*)$)");
  std::istringstream in(log);
  std::string line, result;
  while (std::getline(in, line)) {
    std::smatch m;
    if (line.empty()) continue;
    const bool matched = std::regex_match(line, m, mesaRe) || std::regex_match(line, m, nvidiaRe);
    if (matched && m[1].length() < 10 && m[2].length() < 10) {
      unsigned long long index = std::stoull(m[1].str());
      unsigned long long lineNo = std::stoull(m[2].str());
      // A line number past the first file's range carries its file (see lineDirective).
      if (lineNo >> kFileLineShift) {
        index = lineNo >> kFileLineShift;
        lineNo &= (1ull << kFileLineShift) - 1;
      }
      const std::string file = index < files.size() ? files[index] : "<source " + std::to_string(index) + ">";
      result += file + ":" + std::to_string(lineNo) + ": " + m[3].str() + "\n";
    } else {
      result += line + "\n";
    }
  }
  if (!result.empty() && result.back() == '\n') result.pop_back();
  return result;
}

}  // namespace pbr
