#include "app/args.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace pbr {

std::string sizeText(glm::ivec2 size) { return std::to_string(size.x) + "x" + std::to_string(size.y); }

std::string numberText(double value) {
  std::ostringstream out;
  out << value;  // %g, six significant digits: every default is a short decimal
  return out.str();
}

Args::Args(const std::vector<OptionSpec>& specs, const std::vector<std::string>& argv, bool takesOperands)
    : specs_(specs) {
  for (size_t i = 0; i < argv.size(); ++i) {
    std::string arg = argv[i];
    if (arg == "--help" || arg == "-h") {
      help_ = true;
      continue;
    }
    std::string value;
    bool inlineValue = false;
    if (const size_t eq = arg.find('='); arg.rfind("--", 0) == 0 && eq != std::string::npos) {
      value = arg.substr(eq + 1);
      arg = arg.substr(0, eq);
      inlineValue = true;
    }
    auto spec = std::find_if(specs.begin(), specs.end(), [&](const OptionSpec& s) { return s.name == arg; });
    if (spec == specs.end()) {
      if (takesOperands && !arg.empty() && arg[0] != '-') {
        operands_.push_back(arg);
        continue;
      }
      throw UsageError(arg.rfind("-", 0) == 0 ? "unknown option '" + arg + "'" : "unexpected argument '" + arg + "'");
    }
    // A second occurrence would silently override the first: which one the user meant is not ours to guess.
    if (values_.count(arg)) throw UsageError(arg + " is given more than once");
    if (spec->metavar.empty()) {
      if (inlineValue) throw UsageError("option '" + arg + "' takes no value");
      values_[arg] = "1";
      continue;
    }
    if (!inlineValue) {
      // "--lights --size 160x90": the next option is no value, and naming it would blame the wrong argument.
      if (i + 1 >= argv.size() || argv[i + 1].rfind("--", 0) == 0) {
        throw UsageError(arg + " expects a value (" + spec->metavar + ")");
      }
      value = argv[++i];
    }
    if (value.empty()) throw UsageError(arg + " expects a value (" + spec->metavar + "), got an empty one");
    values_[arg] = value;
  }
}

const OptionSpec& Args::spec(const std::string& name) const {
  for (const OptionSpec& s : specs_) {
    if (s.name == name) return s;
  }
  throw std::logic_error("the command reads option " + name + ", which its table lacks");
}

std::string Args::get(const std::string& name) const {
  auto it = values_.find(name);
  return it == values_.end() ? spec(name).defaultValue : it->second;
}

std::string Args::required(const std::string& name) const {
  std::string value = get(name);
  if (value.empty()) throw std::logic_error("the command reads option " + name + ", absent and without a default");
  return value;
}

int Args::getInt(const std::string& name, int lo, int hi) const {
  const std::string s = required(name);
  char* end = nullptr;
  errno = 0;
  const long v = std::strtol(s.c_str(), &end, 10);
  if (*end != '\0' || errno == ERANGE || v < lo || v > hi) {
    throw UsageError(name + " expects an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got '" + s + "'");
  }
  return static_cast<int>(v);
}

float Args::getFloat(const std::string& name, float lo, float hi) const {
  const std::string s = required(name);
  char* end = nullptr;
  const float v = std::strtof(s.c_str(), &end);
  if (*end != '\0' || !std::isfinite(v) || v < lo || v > hi) {
    std::ostringstream range;
    range << "[" << lo << ", " << hi << "]";
    throw UsageError(name + " expects a number in " + range.str() + ", got '" + s + "'");
  }
  return v;
}

glm::ivec2 Args::getSize(const std::string& name) const {
  const std::string s = required(name);
  int w = 0, h = 0;
  char x = 0, extra = 0;
  std::istringstream in(s);
  if (!(in >> w >> x >> h) || (x != 'x' && x != 'X') || (in >> extra) || w < 1 || h < 1 || w > kMaxSizeSide ||
      h > kMaxSizeSide) {
    throw UsageError(name + " expects WIDTHxHEIGHT with each side in [1, " + std::to_string(kMaxSizeSide) + "], got '" +
                     s + "'");
  }
  return {w, h};
}

namespace {

constexpr size_t kDescriptionColumn = 26;
constexpr size_t kHelpWidth = 110;

// Breaks a description into lines at spaces, each at most `width` characters unless one word is longer.
std::vector<std::string> wrapWords(const std::string& text, size_t width) {
  std::vector<std::string> lines(1);
  std::istringstream words(text);
  for (std::string word; words >> word;) {
    if (!lines.back().empty() && lines.back().size() + 1 + word.size() > width) lines.emplace_back();
    lines.back() += (lines.back().empty() ? "" : " ") + word;
  }
  return lines;
}

}  // namespace

std::string Args::helpText(const std::string& usage, const std::string& summary, const std::vector<OptionSpec>& specs) {
  std::ostringstream out;
  out << "usage: " << usage << "\n\n";
  // The summary's long lines wrapped as the descriptions are: a list item ("  name   text") continues under its
  // text, a paragraph at the margin.
  std::istringstream summaryLines(summary);
  for (std::string line; std::getline(summaryLines, line);) {
    if (line.size() <= kHelpWidth) {
      out << line << "\n";
      continue;
    }
    size_t indent = 0;
    if (line[0] == ' ') indent = line.find_first_not_of(' ', line.find(' ', line.find_first_not_of(' ')));
    if (indent == std::string::npos || indent >= kHelpWidth / 2) indent = 0;
    const std::vector<std::string> lines = wrapWords(line.substr(indent), kHelpWidth - indent);
    out << line.substr(0, indent) << lines.front() << "\n";
    for (size_t i = 1; i < lines.size(); ++i) out << std::string(indent, ' ') << lines[i] << "\n";
  }
  out << "\noptions:\n";
  const std::string indent(kDescriptionColumn, ' ');
  for (const OptionSpec& s : specs) {
    std::string left = "  " + s.name + (s.metavar.empty() ? "" : " " + s.metavar);
    // At least two spaces between an option and its description, which is how both are told apart.
    if (left.size() + 2 <= kDescriptionColumn) left.resize(kDescriptionColumn, ' ');
    else left += "\n" + indent;
    // The no-break space keeps "(default" on the line of the value it introduces; it is made a space again below.
    std::string help = s.help;
    if (!s.defaultValue.empty()) help += (help.empty() ? "" : " ") + std::string("(default\x01") + s.defaultValue + ")";
    if (!s.defaultText.empty()) help += (help.empty() ? "" : " ") + std::string("(default:\x01") + s.defaultText + ")";
    std::vector<std::string> lines = wrapWords(help, kHelpWidth - kDescriptionColumn);
    for (std::string& line : lines) std::replace(line.begin(), line.end(), '\x01', ' ');
    out << left << lines.front() << "\n";
    for (size_t i = 1; i < lines.size(); ++i) out << indent << lines[i] << "\n";
  }
  out << "  --help                  show this help\n";
  return out.str();
}

}  // namespace pbr
