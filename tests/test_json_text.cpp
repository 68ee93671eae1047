// JSON text for messages and reports: strings that are not valid UTF-8 are written with U+FFFD, never thrown on.
#include <doctest/doctest.h>

#include <string>

#include <nlohmann/json.hpp>

#include "core/json_text.hpp"
#include "tests/cli_util.hpp"

TEST_CASE("json text: a quoted string cut inside a multi-byte character is still quoted, not thrown on") {
  // 100 two-byte characters: the 60-character cut falls inside one of them.
  std::string greek;
  for (int i = 0; i < 100; ++i) greek += "\xce\xa4";
  std::string quoted;
  CHECK_NOTHROW(quoted = pbr::quoteJson(nlohmann::json(greek)));
  CHECK(quoted.rfind("\"\xce\xa4\xce\xa4", 0) == 0);
  CHECK(quoted.size() < 80);
  // A path with a byte that is no UTF-8 at all (Linux file names are bytes) reaches a report as U+FFFD.
  CHECK(pbr::jsonText(nlohmann::json("scene-\xff.json")) == "\"scene-\xef\xbf\xbd.json\"");
}

TEST_CASE("json text: a scene whose bad value is such a string is refused with one line") {
  const pbr::test::TempDir dir;
  std::string greek;
  for (int i = 0; i < 100; ++i) greek += "\xce\xa4";
  const std::string scene = dir.write("greek.json", R"({"camera": {"position": [0, 2, 6], "target": [0, 0, 0]},
                                                       "exposure": ")" + greek + "\"}");
  const pbr::test::PbrRun run = pbr::test::runPbr(dir, {"render", "--scene", scene, "--size", "32x18", "--out",
                                                        dir.file("f.png")});
  CHECK(run.exitCode == 1);
  CHECK(pbr::test::isOneLine(run.err));
  CHECK(run.err.find("greek.json:") != std::string::npos);
  CHECK(run.err.find("exposure: expected a number in [0, 1e+06], got \"") != std::string::npos);
}
