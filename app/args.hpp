#pragma once
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>

namespace pbr {

// A malformed command line: reported as one line, exit code 2.
// The largest side getSize accepts (GL_MAX_TEXTURE_SIZE on llvmpipe and most GPUs).
constexpr int kMaxSizeSide = 16384;

class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// One option of a command. The table of them is the one place a default lives: an absent option reads as its
// `defaultValue`, and the help prints that same string, so the two cannot drift apart. Where what an absent option
// means depends on the input (the scene's exposure), `defaultText` says so in the help and the command checks
// has() before reading; help strings themselves never state a default.
struct OptionSpec {
  OptionSpec(std::string name_, std::string metavar_, std::string help_, std::string defaultValue_ = {},
             std::string defaultText_ = {})
      : name(std::move(name_)), metavar(std::move(metavar_)), help(std::move(help_)),
        defaultValue(std::move(defaultValue_)), defaultText(std::move(defaultText_)) {}

  std::string name;          // "--lights"
  std::string metavar;       // "N"; empty for a flag
  std::string help;
  std::string defaultValue;  // printed "(default V)"; what get*() read when the option is absent
  std::string defaultText;   // printed "(default: TEXT)" for a default that is no single value
};

std::string sizeText(glm::ivec2 size);  // "1280x720", as --size takes it
std::string numberText(double value);    // "60", "0.25": the shortest form that reads back the same float

// Parses "--name value", "--name=value" and flags against a fixed list of options. With `takesOperands`, the other
// arguments not starting with '-' (input files) are kept in order as operands; otherwise they are refused.
class Args {
 public:
  Args(const std::vector<OptionSpec>& specs, const std::vector<std::string>& argv, bool takesOperands = false);

  bool helpRequested() const { return help_; }
  bool has(const std::string& name) const { return values_.count(name) != 0; }
  // The given value, else the option's defaultValue. get() reads "" for an absent option without one (an output
  // not asked for); the typed getters need a value, and reading an option the table lacks is a std::logic_error.
  std::string get(const std::string& name) const;
  int getInt(const std::string& name, int lo, int hi) const;
  float getFloat(const std::string& name, float lo, float hi) const;
  glm::ivec2 getSize(const std::string& name) const;  // "WxH"
  const std::vector<std::string>& operands() const { return operands_; }

  static std::string helpText(const std::string& usage, const std::string& summary,
                              const std::vector<OptionSpec>& specs);

 private:
  const OptionSpec& spec(const std::string& name) const;
  std::string required(const std::string& name) const;

  std::vector<OptionSpec> specs_;
  std::map<std::string, std::string> values_;
  std::vector<std::string> operands_;
  bool help_ = false;
};

}  // namespace pbr
