// JSON text for messages and reports: strings that are not valid UTF-8 are written with U+FFFD, never thrown on.
#include <doctest/doctest.h>

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/scene/json_file.hpp"
#include "core/scene/json_text.hpp"
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

TEST_CASE("json text: a key given twice in one object refuses a scene, and is a warning in glTF, --strict refusing it") {
  const pbr::test::TempDir dir;
  // A second "lights" would silently replace the first: a black frame.
  const std::string scene = dir.write("twice.json", R"({"camera": {"position": [0, 2, 6], "target": [0, 0, 0]},
      "lights": [{"position": [0, 1, 0], "radius": 4, "color": [1, 1, 1], "power": 100}],
      "objects": [{"shape": "plane"}], "lights": []})");
  const pbr::test::PbrRun run = pbr::test::runPbr(dir, {"render", "--scene", scene, "--size", "32x18", "--out",
                                                        dir.file("f.png")});
  CHECK(run.exitCode == 1);
  CHECK(pbr::test::isOneLine(run.err));
  CHECK(run.err.find("twice.json: lights: given twice in one object") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(dir.file("f.png")));

  // glTF, as JSON.parse and the viewers read it: the later value, each duplicate noted by its path.
  std::vector<std::string> duplicates;
  const nlohmann::json doc = pbr::parseJsonText(R"({"asset": {"version": "2.0", "version": "2.0"},
      "nodes": [{"name": "a"}, {"name": "b", "name": "c"}]})", "m.gltf", &duplicates);
  CHECK(duplicates == std::vector<std::string>{"asset.version", "nodes[1].name"});
  CHECK(doc["nodes"][1]["name"] == "c");
  const std::string gltf = dir.write("twice.gltf", R"({"asset": {"version": "2.0"}, "asset": {"version": "2.0"}})");
  const pbr::test::PbrRun strict = pbr::test::runPbr(dir, {"render", "--scene", gltf, "--strict", "--size", "32x18",
                                                           "--out", dir.file("g.png")});
  CHECK(strict.exitCode == 1);
  CHECK(pbr::test::isOneLine(strict.err));
  CHECK(strict.err.find("twice.gltf: asset: given twice in one object (--strict refuses it)") != std::string::npos);
}
