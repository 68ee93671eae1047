#pragma once
// Checks of how `pbr` refuses what it cannot do: exit code, one short line on stderr naming the culprit.
#include <string>
#include <vector>

#include "tests/cli_util.hpp"

namespace pbr::test {

// `pbr render` of one tiny frame, 32x18 unless `extra` gives a --size.
std::vector<std::string> tinyRender(const std::vector<std::string>& extra);

// stderr is one line under 300 characters holding `name`.
void checkOneLineNaming(const PbrRun& run, const std::string& name);

// Renders `scene` (with the options `extra`) and checks the refusal: exit 1, one line under 300 characters naming
// the file and holding every part, no frame.
void checkRefused(const TempDir& dir, const std::string& scene, const std::vector<std::string>& parts,
                  const std::vector<std::string>& extra = {});

}  // namespace pbr::test
