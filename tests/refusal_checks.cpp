#include "tests/refusal_checks.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>

namespace pbr::test {

std::vector<std::string> tinyRender(const std::vector<std::string>& extra) {
  std::vector<std::string> args = {"render", "--frames", "1", "--warmup", "0", "--lights", "8"};
  if (std::find(extra.begin(), extra.end(), "--size") == extra.end()) args.insert(args.end(), {"--size", "32x18"});
  args.insert(args.end(), extra.begin(), extra.end());
  return args;
}

void checkOneLineNaming(const PbrRun& run, const std::string& name) {
  CHECK(isOneLine(run.err));
  CHECK(run.err.size() < 300);
  CHECK(run.err.find(name) != std::string::npos);
}

void checkRefused(const TempDir& dir, const std::string& scene, const std::vector<std::string>& parts,
                  const std::vector<std::string>& extra) {
  const std::string out = dir.file("frame.png");
  std::vector<std::string> args = {"render", "--scene", scene, "--size", "32x18", "--frames", "1", "--warmup", "0",
                                   "--out", out};
  args.insert(args.end(), extra.begin(), extra.end());
  const PbrRun run = runPbr(dir, args);
  CAPTURE(scene);
  CAPTURE(run.err);
  CHECK(run.exitCode == 1);
  checkOneLineNaming(run, std::filesystem::path(scene).filename().string());
  for (const std::string& part : parts) CHECK(run.err.find(part) != std::string::npos);
  CHECK(!std::filesystem::exists(out));
}

}  // namespace pbr::test
