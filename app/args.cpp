#include "app/args.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace pbr {

Args::Args(const std::vector<OptionSpec>& specs, const std::vector<std::string>& argv, bool takesOperands) {
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

std::string Args::get(const std::string& name, const std::string& fallback) const {
  auto it = values_.find(name);
  return it == values_.end() ? fallback : it->second;
}

int Args::getInt(const std::string& name, int fallback, int lo, int hi) const {
  auto it = values_.find(name);
  if (it == values_.end()) return fallback;
  const std::string& s = it->second;
  char* end = nullptr;
  errno = 0;
  const long v = std::strtol(s.c_str(), &end, 10);
  if (s.empty() || *end != '\0' || errno == ERANGE || v < lo || v > hi) {
    throw UsageError(name + " expects an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got '" + s + "'");
  }
  return static_cast<int>(v);
}

float Args::getFloat(const std::string& name, float fallback, float lo, float hi) const {
  auto it = values_.find(name);
  if (it == values_.end()) return fallback;
  const std::string& s = it->second;
  char* end = nullptr;
  const float v = std::strtof(s.c_str(), &end);
  if (s.empty() || *end != '\0' || !std::isfinite(v) || v < lo || v > hi) {
    std::ostringstream range;
    range << "[" << lo << ", " << hi << "]";
    throw UsageError(name + " expects a number in " + range.str() + ", got '" + s + "'");
  }
  return v;
}

glm::ivec2 Args::getSize(const std::string& name, glm::ivec2 fallback) const {
  auto it = values_.find(name);
  if (it == values_.end()) return fallback;
  const std::string& s = it->second;
  int w = 0, h = 0;
  char x = 0, extra = 0;
  std::istringstream in(s);
  if (!(in >> w >> x >> h) || (x != 'x' && x != 'X') || (in >> extra) || w < 1 || h < 1 || w > 16384 || h > 16384) {
    throw UsageError(name + " expects WIDTHxHEIGHT with each side in [1, 16384], got '" + s + "'");
  }
  return {w, h};
}

std::string Args::helpText(const std::string& usage, const std::string& summary, const std::vector<OptionSpec>& specs) {
  std::ostringstream out;
  out << "usage: " << usage << "\n\n" << summary << "\n\noptions:\n";
  for (const OptionSpec& s : specs) {
    std::string left = "  " + s.name + (s.metavar.empty() ? "" : " " + s.metavar);
    if (left.size() < 26) left.resize(26, ' ');
    else left += "\n" + std::string(26, ' ');
    out << left << s.help << "\n";
  }
  out << "  --help                  show this help\n";
  return out.str();
}

}  // namespace pbr
