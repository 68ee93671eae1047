// A glTF model whose buffer lies outside its folder: refused by default, rendered with --allow-outside-uris.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "tests/cli_util.hpp"
#include "tests/gltf_builder.hpp"
#include "tests/refusal_checks.hpp"

using namespace pbr::test;

TEST_CASE("hostile scenes: URIs that leave the model's folder are refused unless --allow-outside-uris") {
  const TempDir dir;
  GltfBuilder b = quadModel();
  std::filesystem::create_directories(dir.path() / "model");
  const std::string path = b.writeGltf(dir.path() / "model", "outside");
  std::filesystem::rename(dir.path() / "model" / "outside.bin", dir.path() / "outside.bin");
  nlohmann::json doc = nlohmann::json::parse(pbr::test::readFile(path));
  doc["buffers"][0]["uri"] = "../outside.bin";
  std::ofstream(path) << doc.dump();
  checkRefused(dir, path, {"buffers[0].uri: '../outside.bin' leaves the model's folder (--allow-outside-uris"});

  const std::string out = dir.file("allowed.png");
  const PbrRun run = pbr::test::runPbr(dir, {"render", "--scene", path, "--size", "32x18", "--frames", "1",
                                             "--warmup", "0", "--out", out, "--allow-outside-uris"});
  CAPTURE(run.err);
  CHECK(run.exitCode == 0);
  CHECK(std::filesystem::exists(out));

  doc["buffers"][0]["uri"] = "../../../../../../../../etc/passwd";
  std::ofstream(path) << doc.dump();
  checkRefused(dir, path, {"buffers[0].uri: '../../../../../../../../etc/passwd' leaves the model's folder"});
}
