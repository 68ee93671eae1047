#include "app/bench/chart_script.hpp"

#include <cstdlib>

namespace pbr {

namespace {

std::string shellQuote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

}  // namespace

bool runChartScript(const std::string& script, const std::vector<std::string>& args) {
  std::string cmd = "/usr/bin/python3 " + shellQuote(std::string(PBR_SCRIPT_DIR) + "/" + script);
  for (const std::string& a : args) cmd += " " + shellQuote(a);
  return std::system(cmd.c_str()) == 0;
}

}  // namespace pbr
