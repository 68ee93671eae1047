#pragma once
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

namespace pbr {

// A malformed command line: reported as one line, exit code 2.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct OptionSpec {
  std::string name;     // "--lights"
  std::string metavar;  // "N"; empty for a flag
  std::string help;
};

// Parses "--name value", "--name=value" and flags against a fixed list of options. With `takesOperands`, the other
// arguments not starting with '-' (input files) are kept in order as operands; otherwise they are refused.
class Args {
 public:
  Args(const std::vector<OptionSpec>& specs, const std::vector<std::string>& argv, bool takesOperands = false);

  bool helpRequested() const { return help_; }
  bool has(const std::string& name) const { return values_.count(name) != 0; }
  std::string get(const std::string& name, const std::string& fallback) const;
  int getInt(const std::string& name, int fallback, int lo, int hi) const;
  float getFloat(const std::string& name, float fallback, float lo, float hi) const;
  glm::ivec2 getSize(const std::string& name, glm::ivec2 fallback) const;  // "WxH"
  const std::vector<std::string>& operands() const { return operands_; }

  static std::string helpText(const std::string& usage, const std::string& summary,
                              const std::vector<OptionSpec>& specs);

 private:
  std::map<std::string, std::string> values_;
  std::vector<std::string> operands_;
  bool help_ = false;
};

}  // namespace pbr
