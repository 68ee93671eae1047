// Input the loaders do not understand is named, not silently dropped: a scene key nobody reads is a warning (with
// --strict, the file is refused), a glTF extension used but not implemented is a warning. Every command here fails
// or renders before making a GL context (`pbr reference` renders on the CPU).
#include <doctest/doctest.h>

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/scene/json_field.hpp"
#include "core/scene/scene.hpp"
#include "core/scene/scene_json.hpp"
#include "tests/cli_util.hpp"
#include "tests/gltf_builder.hpp"

namespace fs = std::filesystem;
using pbr::test::CapturedStderr;
using pbr::test::PbrRun;
using pbr::test::runPbr;
using pbr::test::TempDir;

namespace {

// A valid scene but for three misspelt keys at three depths: exposur, lights[1].colour and
// objects[0].material.roughnes (the order nlohmann keeps an object's keys in, alphabetical).
const std::string kMisspelt = R"({
  "camera": {"position": [0, 2, 5], "target": [0, 0.5, 0]},
  "exposur": 2,
  "objects": [{"shape": "sphere", "material": {"roughnes": 0.2, "metalness": 1}}],
  "lights": [{"position": [1, 2, 2], "luminous_power": 200, "radius": 8},
             {"position": [-1, 2, 2], "colour": [1, 0, 0], "luminous_power": 100, "radius": 8}],
  "random_lights": {"count": 2, "bounds": [[-1, 0.5, -1], [1, 1, 1]], "radius": [1, 2], "luminous_power": [5, 10]}
})";

std::string misspeltWarnings(const std::string& file) {
  return file + ": exposur: unknown key\n" + file + ": lights[1].colour: unknown key\n" + file +
         ": objects[0].material.roughnes: unknown key\n";
}

std::vector<std::string> referenceRun(const std::string& scene, const std::string& out) {
  return {"reference", "--scene", scene, "--size", "16x9", "--threads", "2", "--hdr", out};
}

}  // namespace

TEST_CASE("unknown input: misspelt scene keys are named one line each, and the scene renders anyway") {
  const TempDir dir;
  const std::string scene = dir.write("misspelt.json", kMisspelt);
  const std::string out = dir.file("frame.pfm");
  const PbrRun run = runPbr(dir, referenceRun(scene, out));
  CHECK(run.exitCode == 0);
  CHECK(run.err == misspeltWarnings(scene));
  CHECK(fs::exists(out));
}

TEST_CASE("unknown input: a misspelt key is read as absent, and a file loaded again does not repeat its warnings") {
  const TempDir dir;
  const std::string path = dir.write("again.json", kMisspelt);
  const CapturedStderr captured;
  const pbr::Scene first = pbr::loadSceneFile(path);
  CHECK(first.exposure == pbr::Scene{}.exposure);
  CHECK(first.objects[0].material.roughness == pbr::Material{}.roughness);
  CHECK(first.lights[1].color == pbr::PointLight{}.color);
  pbr::loadSceneFile(path, 5);
  CHECK(captured.text() == misspeltWarnings(path));
}

TEST_CASE("unknown input: --strict refuses the first unknown key with exit 1, in every command that loads scenes") {
  const TempDir dir;
  const std::string scene = dir.write("strict.json", kMisspelt);
  const std::string out = dir.file("frame.png");
  const std::vector<std::vector<std::string>> commands = {
      {"render", "--scene", scene, "--size", "32x18", "--frames", "1", "--warmup", "0", "--out", out},
      {"bench", "--scene", scene},
      {"reference", "--scene", scene, "--hdr", dir.file("frame.pfm")},
      {"accuracy", "--scenes", scene, "--out-dir", dir.file("accuracy")},
      {"view", "--scene", scene}};
  for (std::vector<std::string> args : commands) {
    CAPTURE(args[0]);
    args.push_back("--strict");
    const PbrRun run = runPbr(dir, args);
    CHECK(run.exitCode == 1);
    CHECK(run.err == "pbr " + args[0] + ": " + scene + ": exposur: unknown key\n");
    const PbrRun help = runPbr(dir, {args[0], "--help"});
    CHECK(help.out.find("--strict") != std::string::npos);
  }
  CHECK(!fs::exists(out));
  CHECK(!fs::exists(dir.file("frame.pfm")));
  CHECK(!fs::exists(dir.file("accuracy")));
}

TEST_CASE("unknown input: only keys of objects that were read are searched, and a key looked up is known") {
  const nlohmann::json doc = nlohmann::json::parse(R"({
    "checked": {"x": 1},
    "list": [{"n": 1}, {"n": 2, "extra": {"deep": 1}}],
    "read": {"n": 1, "typo": 2},
    "unread": {"deep": 1}
  })");
  const auto read = [&doc](const std::string& file) {
    const pbr::JsonField root(doc, file);
    CHECK(root["checked"].present());  // looked up only, as keys that are refused when present are
    CHECK(root["read"]["n"].number(pbr::NumberRule::any()) == 1.0f);
    for (const pbr::JsonField& item : root["list"].items()) item["n"].number(pbr::NumberRule::any());
    return root;
  };
  {
    const CapturedStderr captured;
    read("fields.json").reportUnknownKeys(false);
    CHECK(captured.text() == "fields.json: list[1].extra: unknown key\n"
                             "fields.json: read.typo: unknown key\n"
                             "fields.json: unread: unknown key\n");
  }
  CHECK_THROWS_WITH_AS(read("strict.json").reportUnknownKeys(true), "strict.json: list[1].extra: unknown key",
                       pbr::SceneError);
}

TEST_CASE("unknown input: a hostile key is named in one line of bounded length") {
  const nlohmann::json doc = {{"two\nlines", 1}, {std::string(100000, 'k'), 2}, {"known", 3}};
  const pbr::JsonField root(doc, "hostile.json");
  root["known"].number(pbr::NumberRule::any());
  const CapturedStderr captured;
  root.reportUnknownKeys(false);
  const std::string text = captured.text();
  CHECK(text.substr(0, text.find('\n') + 1).size() <= 401);
  CHECK(text.substr(text.find('\n') + 1) == "hostile.json: two lines: unknown key\n");
}

TEST_CASE("unknown input: every scenes/*.json file loads without a warning") {
  int files = 0;
  for (const fs::directory_entry& entry : fs::directory_iterator(fs::path(PBR_SOURCE_DIR) / "scenes")) {
    if (entry.path().extension() != ".json") continue;
    CAPTURE(entry.path());
    const CapturedStderr captured;
    CHECK_NOTHROW(pbr::loadSceneFile(entry.path().string(), -1, {}, true));
    CHECK(captured.text().empty());
    ++files;
  }
  CHECK(files >= 8);
}

TEST_CASE("unknown input: glTF extensions used but not implemented are listed once, --strict or not") {
  const TempDir dir;
  pbr::test::GltfBuilder model = pbr::test::quadModel();
  model.doc["extensionsUsed"] = {"KHR_materials_iridescence", "KHR_lights_punctual", "KHR_materials_anisotropy"};
  const std::string path = model.writeGltf(dir.path(), "model");
  // Placed twice: the second load of the file has nothing new to say.
  const std::string scene = dir.write("scene.json", R"({
    "camera": {"position": [0, 0, 5], "target": [0, 0, 0]},
    "objects": [{"gltf": "model.gltf"}, {"gltf": "model.gltf", "transform": {"translate": [1, 0, 0]}}],
    "lights": [{"position": [0, 0, 3], "luminous_power": 100, "radius": 10}]
  })");
  const std::string out = dir.file("frame.pfm");
  std::vector<std::string> args = referenceRun(scene, out);
  args.push_back("--strict");
  const PbrRun run = runPbr(dir, args);
  CHECK(run.exitCode == 0);
  CHECK(run.err ==
        path + ": extensionsUsed not implemented, ignored: KHR_materials_iridescence, KHR_materials_anisotropy\n");
  CHECK(fs::exists(out));
}
