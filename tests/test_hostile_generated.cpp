// Generated hostile input, from fixed seeds: every value of a valid scene file, of a valid glTF file and of valid
// command lines replaced in turn by values of other types and ranges. The contract each case checks: the input
// loads (and then passes the scene validation) or is refused with one line under 300 characters naming the file;
// a command exits 0, 1, 2 or 3 (never by a signal, never after the time limit) with one line on stderr when it
// fails, and leaves no temporary file behind.
#include <doctest/doctest.h>
#include <sys/wait.h>

#include <filesystem>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/scene/gltf_loader.hpp"
#include "core/scene/scene_json.hpp"
#include "tests/cli_util.hpp"
#include "tests/gltf_builder.hpp"

using nlohmann::json;
using pbr::test::TempDir;

namespace {

// Values of every JSON type, and numbers at and past the limits the readers check.
const std::vector<json>& replacements() {
  static const std::vector<json> values = {
      json(nullptr), json(true), json(-1), json(0), json(1e300), json(-1e-300), json(4294967296.0), json(0.5),
      json("NaN"), json(""), json::array(), json::array({1, 2}), json::array({"x", 1, 2}), json::object(),
      json::object({{"x", 1}}), json(1e12), json(3.5e38)};
  return values;
}

// The JSON pointer of every value in `doc` (objects' members and arrays' elements, depth first).
void collectPointers(const json& doc, const std::string& at, std::vector<std::string>& out) {
  if (doc.is_object()) {
    for (auto it = doc.begin(); it != doc.end(); ++it) {
      const std::string p = at + "/" + it.key();
      out.push_back(p);
      collectPointers(it.value(), p, out);
    }
  } else if (doc.is_array()) {
    for (size_t i = 0; i < doc.size(); ++i) {
      const std::string p = at + "/" + std::to_string(i);
      out.push_back(p);
      collectPointers(doc[i], p, out);
    }
  }
}

// Runs `load` on each of `count` mutants of `valid` (seeded): a value replaced, or a member removed. Each must load
// or be refused with one line naming `name`.
void checkMutants(const json& valid, uint32_t seed, int count, const std::string& name,
                  const std::function<void(const json&)>& load) {
  std::vector<std::string> pointers;
  collectPointers(valid, "", pointers);
  std::mt19937 random(seed);
  int refused = 0;
  for (int i = 0; i < count; ++i) {
    json mutant = valid;
    const std::string pointer = pointers[random() % pointers.size()];
    const json::json_pointer p(pointer);
    if (random() % 5 == 0) {
      mutant[p.parent_pointer()].is_object() ? void(mutant[p.parent_pointer()].erase(p.back())) : void();
    } else {
      mutant[p] = replacements()[random() % replacements().size()];
    }
    CAPTURE(pointer);
    CAPTURE(mutant.dump().substr(0, 400));
    try {
      load(mutant);
    } catch (const pbr::SceneError& e) {
      const std::string message = e.what();
      ++refused;
      CHECK(message.find(name) != std::string::npos);
      CHECK(message.find('\n') == std::string::npos);
      CHECK(message.size() < 300);
    }
  }
  MESSAGE(name << ": " << count << " mutants, " << refused << " refused");
  CHECK(refused > count / 4);  // the mutations reach the checks
}

}  // namespace

TEST_CASE("generated hostile input: scene file mutants load valid or are refused in one line naming the file") {
  const TempDir dir;
  const json valid = json::parse(R"({
    "camera": {"position": [0, 2, 6], "target": [0, 0, 0], "fov_y_deg": 50, "near": 0.1, "far": 100},
    "exposure": 1, "ambient": 0.02,
    "objects": [{"shape": "sphere", "transform": {"translate": [0, 1, 0], "scale": 2},
                 "material": {"base_color": [0.8, 0.2, 0.2], "roughness": 0.4, "metalness": 0, "alpha": 0.5,
                              "alpha_mode": "blend"}},
                {"shape": "plane", "transform": {"scale": 10}}],
    "lights": [{"position": [1, 3, 1], "color": [1, 1, 1], "luminous_power": 100, "radius": 5},
               {"type": "spot", "position": [0, 3, 0], "direction": [0, -1, 0], "luminous_power": 100,
                "radius": 6, "inner_angle_deg": 10, "outer_angle_deg": 30},
               {"type": "directional", "direction": [0, -1, 0], "illuminance_lux": 2}],
    "random_lights": {"count": 4, "seed": 2, "bounds": [[-1, 0, -1], [1, 2, 1]], "radius": [1, 2],
                      "luminous_power": [10, 20]}})");
  const std::string path = dir.file("mutant.json");
  pbr::test::CapturedStderr warnings;  // unknown keys and the like: warnings, not failures
  checkMutants(valid, 20261127, 400, "mutant.json", [&](const json& mutant) {
    dir.write("mutant.json", mutant.dump());
    const pbr::Scene scene = pbr::loadSceneFile(path);
    pbr::validateScene(scene, path);
  });
}

TEST_CASE("generated hostile input: glTF mutants load valid or are refused in one line naming the file") {
  const TempDir dir;
  pbr::test::GltfBuilder b = pbr::test::quadModel();
  b.doc["materials"] = {{{"pbrMetallicRoughness", {{"baseColorFactor", {1, 0.5, 0.2, 1}}, {"roughnessFactor", 0.5}}},
                         {"alphaMode", "MASK"}, {"alphaCutoff", 0.3}, {"doubleSided", true}}};
  b.doc["meshes"][0]["primitives"][0]["material"] = 0;
  b.doc["extensionsUsed"] = {"KHR_lights_punctual"};
  b.doc["extensions"]["KHR_lights_punctual"]["lights"] = {
      {{"type", "spot"}, {"intensity", 5.0}, {"range", 4.0}, {"spot", {{"outerConeAngle", 0.6}}}}};
  b.doc["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", 0.8}, {"znear", 0.1}, {"zfar", 50.0}}}}};
  b.doc["nodes"].push_back({{"translation", {0, 0, 3}}, {"rotation", {0, 0, 0, 1}}, {"camera", 0},
                            {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
  b.doc["scenes"][0]["nodes"].push_back(1);
  // The buffer stays as written (its data: URI is not mutated): the structure around it is.
  const std::string written = b.writeGltf(dir.path(), "base");
  const json valid = json::parse(pbr::test::readFile(written));
  json structure = valid;
  structure.erase("buffers");
  const std::string path = dir.file("mutant.gltf");
  pbr::test::CapturedStderr warnings;
  checkMutants(structure, 1127, 400, "mutant.gltf", [&](const json& mutant) {
    json file = mutant;
    file["buffers"] = valid["buffers"];
    dir.write("mutant.gltf", file.dump());
    pbr::Scene scene;
    pbr::appendGltf(scene, path);
    pbr::validateScene(scene, path);
  });
}

TEST_CASE("generated hostile input: mutated command lines exit 0 to 3 with one line on failure, leaving nothing") {
  const TempDir dir;
  const std::string scene = dir.write("s.json", R"({"camera": {"position": [0, 2, 5], "target": [0, 0, 0]},
    "objects": [{"shape": "sphere"}], "lights": [{"position": [1, 2, 2], "radius": 5, "luminous_power": 100}]})");
  // Valid command lines, each option with a value; the mutants replace a value, drop one, or repeat an option, or
  // keep it as written.
  const std::vector<std::vector<std::string>> valid = {
      {"render", "--scene", scene, "--size", "16x9", "--frames", "1", "--warmup", "0", "--out", "out/f.png"},
      {"render", "--scene", "default", "--lights", "8", "--size", "16x9", "--frames", "1", "--hdr", "out/f.pfm"},
      {"reference", "--scene", scene, "--size", "8x8", "--hdr", "out/r.pfm"},
      {"render", "--scene", scene, "--size", "16x9", "--frames", "1", "--variant", "ndf=beckmann", "--shadows", "on",
       "--shadow-filter", "hard", "--json", "out/f.json"},
  };
  // Junk, and values valid for some options ("2", "8x8", "none", "out/g.png").
  const std::vector<std::string> junk = {"", "-1", "0", "1e999", "nan", "x", "16384x16384x2", "--size", "/dev/full",
                                         "999999999999", "out", "s.json", "../../etc/passwd", "1x0", "2", "8x8",
                                         "none", "out/g.png"};
  std::mt19937 random(42);
  int exits[6] = {};  // -1 (a signal), 0, 1, 2, 3, more
  for (int i = 0; i < 40; ++i) {
    std::vector<std::string> args = valid[random() % valid.size()];
    const size_t at = 1 + 2 * (random() % ((args.size() - 1) / 2));  // an option; its value follows
    switch (random() % 4) {
      case 0: args[at + 1] = junk[random() % junk.size()]; break;
      case 1: args.erase(args.begin() + long(at) + 1); break;
      case 2: args.insert(args.end(), {args[at], junk[random() % junk.size()]}); break;
      default: break;  // as written: it must render
    }
    std::string line;
    for (const std::string& a : args) line += a + " ";
    CAPTURE(line);
    // A bounded time: a hang fails the case (timeout's exit 124) rather than the suite.
    const pbr::test::PbrRun run = pbr::test::runPbr(dir, args, "cd " + dir.path().string() + "; timeout 60 ");
    CHECK(run.exitCode >= 0);
    CHECK(run.exitCode <= 3);
    ++exits[std::min(run.exitCode + 1, 5)];
    if (run.exitCode != 0) {
      CHECK(pbr::test::isOneLine(run.err));
      CHECK(run.err.size() < 300);
    }
    if (std::filesystem::exists(dir.path() / "out")) {
      for (const auto& entry : std::filesystem::directory_iterator(dir.path() / "out")) {
        CHECK(entry.path().filename().string().rfind(".", 0) != 0);  // no temporary left
      }
    }
  }
  MESSAGE("exit codes 0/1/2/3: " << exits[1] << "/" << exits[2] << "/" << exits[3] << "/" << exits[4]);
  CHECK(exits[1] > 0);  // some mutants still render
  CHECK(exits[3] > 0);  // and some are refused as command lines
}
