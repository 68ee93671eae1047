#pragma once
#include <string>
#include <vector>

namespace pbr {

// Runs one of the project's chart scripts (scripts/NAME) with Debian's /usr/bin/python3, which has
// python3-matplotlib (scripts/install-deps.sh); a pyenv python on PATH may not. True when it succeeded.
bool runChartScript(const std::string& script, const std::vector<std::string>& args);

}  // namespace pbr
