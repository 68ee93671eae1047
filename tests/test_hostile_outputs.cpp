// Outputs that cannot be written and frames too large to allocate: each fails with exit code 1 or 2, one short line
// on stderr naming the file or option, and no file left behind.
#include <doctest/doctest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "core/scene/image.hpp"
#include "renderer/driver_limits.hpp"
#include "renderer/renderer.hpp"
#include "tests/cli_util.hpp"
#include "tests/gl_test_context.hpp"
#include "tests/refusal_checks.hpp"

namespace fs = std::filesystem;
using pbr::test::checkOneLineNaming;
using pbr::test::readFile;
using pbr::test::runPbr;
using pbr::test::TempDir;
using pbr::test::tinyRender;
using Run = pbr::test::PbrRun;

namespace {

// Every entry of `folder`, temporaries (".NAME.PID.N.tmp") included.
std::vector<std::string> entries(const fs::path& folder) {
  std::vector<std::string> names;
  if (!fs::exists(folder)) return names;
  for (const fs::directory_entry& e : fs::directory_iterator(folder)) names.push_back(e.path().filename().string());
  return names;
}

// Nothing was rendered: the failure came before the first frame.
void checkNotRendered(const Run& run) { CHECK(run.out.find("first frame") == std::string::npos); }

}  // namespace

TEST_CASE("hostile outputs: a device that refuses the bytes (/dev/full) fails with exit 1 naming it") {
  PBR_REQUIRE_GL();
  const TempDir dir;
  for (const char* option : {"--out", "--json"}) {
    CAPTURE(option);
    const Run run = runPbr(dir, tinyRender({option, "/dev/full"}));
    CHECK(run.exitCode == 1);
    checkOneLineNaming(run, "/dev/full: cannot write: No space left on device");
    CHECK(run.out.find("wrote") == std::string::npos);
  }
  const Run bench = runPbr(dir, {"bench", "--scene", "default", "--size", "32x18", "--lights", "8", "--culling",
                                 "clustered", "--model", "pbr", "--warmup", "1", "--frames", "1", "--csv", "/dev/full"});
  CHECK(bench.exitCode == 1);
  // bench reports its progress on stderr; the error is its last line.
  CHECK(bench.err.find("/dev/full: cannot write: No space left on device") != std::string::npos);
}

TEST_CASE("hostile outputs: a file over the size limit (a full disk) leaves the previous file whole and no temporary") {
  PBR_REQUIRE_GL();
  const TempDir dir;
  const fs::path folder = dir.path() / "out";
  fs::create_directories(folder);
  const std::string png = (folder / "f.png").string(), pfm = (folder / "f.pfm").string();
  const std::string previous = "the previous capture";
  dir.write("out/f.png", previous);
  // RLIMIT_FSIZE makes write(2) fail with EFBIG past 16 blocks, as a full disk fails it with ENOSPC; pbr ignores
  // SIGXFSZ, which would otherwise kill it without a word, so that the failure reaches the writer.
  const std::string limit = "ulimit -f 16; ";
  const Run run = runPbr(dir, {"render", "--size", "320x180", "--frames", "1", "--warmup", "0", "--out", png}, limit);
  CHECK(run.exitCode == 1);
  checkOneLineNaming(run, png + ": cannot write: File too large");
  CHECK(readFile(png) == previous);
  const Run hdr = runPbr(dir, {"render", "--size", "320x180", "--frames", "1", "--warmup", "0", "--hdr", pfm}, limit);
  CHECK(hdr.exitCode == 1);
  checkOneLineNaming(hdr, pfm + ": cannot write: File too large");
  CHECK(entries(folder) == std::vector<std::string>{"f.png"});
}

TEST_CASE("hostile outputs: a folder that cannot be made fails before rendering, naming the file") {
  PBR_REQUIRE_GL();
  const TempDir dir;
  const std::string notAFolder = dir.write("plain-file", "x");
  for (const char* option : {"--out", "--hdr", "--json"}) {
    CAPTURE(option);
    const std::string name = std::string("f") + (option == std::string("--out") ? ".png" : option == std::string("--hdr") ? ".exr" : ".json");
    const std::string path = notAFolder + "/sub/" + name;
    const Run run = runPbr(dir, tinyRender({option, path}));
    CHECK(run.exitCode == 1);
    checkOneLineNaming(run, path + ": cannot write: cannot make the folder");
    checkNotRendered(run);
    CHECK(readFile(notAFolder) == "x");
  }
  const std::string csv = notAFolder + "/sub/bench.csv";
  const Run bench = runPbr(dir, {"bench", "--scene", "default", "--size", "32x18", "--lights", "8", "--csv", csv});
  CHECK(bench.exitCode == 1);
  checkOneLineNaming(bench, csv + ": cannot write");
}

TEST_CASE("hostile outputs: missing folders are made, and a written capture leaves no temporary beside it") {
  PBR_REQUIRE_GL();
  const TempDir dir;
  const fs::path folder = dir.path() / "new" / "sub";
  const Run run = runPbr(dir, tinyRender({"--out", (folder / "f.png").string(), "--hdr", (folder / "f.exr").string(),
                                          "--json", (folder / "f.json").string()}));
  REQUIRE(run.exitCode == 0);
  std::vector<std::string> names = entries(folder);
  std::sort(names.begin(), names.end());
  CHECK(names == std::vector<std::string>{"f.exr", "f.json", "f.png"});
  CHECK(readFile(folder / "f.png").compare(0, 4, "\x89PNG") == 0);
}

TEST_CASE("hostile outputs: a read-only folder fails with exit 1 naming the file") {
  PBR_REQUIRE_GL();
  if (::geteuid() == 0) {
    MESSAGE("skipped: root writes into read-only folders, so the case cannot fail as a user would see it");
    return;
  }
  const TempDir dir;
  const fs::path folder = dir.path() / "read-only";
  fs::create_directories(folder);
  fs::permissions(folder, fs::perms::owner_read | fs::perms::owner_exec);
  const std::string png = (folder / "f.png").string();
  const Run run = runPbr(dir, tinyRender({"--out", png}));
  fs::permissions(folder, fs::perms::owner_all);
  CHECK(run.exitCode == 1);
  checkOneLineNaming(run, png + ": cannot write: Permission denied");
  checkNotRendered(run);
  CHECK(entries(folder).empty());
}

TEST_CASE("hostile outputs: a frame larger than the limits fails before rendering, naming --size") {
  PBR_REQUIRE_GL();
  const TempDir dir;
  const Run huge = runPbr(dir, tinyRender({"--size", "100000x100000"}));
  CHECK(huge.exitCode == 2);
  checkOneLineNaming(huge, "--size expects WIDTHxHEIGHT with each side in [1, 16384], got '100000x100000'");
#if defined(__SANITIZE_ADDRESS__)
  // AddressSanitizer reserves terabytes of address space at start-up: under an address-space limit the process
  // aborts before main, so the memory case runs in the plain build only.
  MESSAGE("memory limit case skipped under AddressSanitizer");
#else
  // Under GL_MAX_TEXTURE_SIZE but over the memory: an address-space limit of 6 GB leaves room for the context and
  // not for 16384x16384 at 104 bytes per pixel (27.9 GB).
  const Run memory = runPbr(dir, tinyRender({"--size", "16384x16384"}), "ulimit -v 6000000; ");
  CHECK(memory.exitCode == 1);
  checkOneLineNaming(memory, "--size 16384x16384: the frame needs about 27.9 GB (104 bytes per pixel)");
  checkNotRendered(memory);
  const Run pairCost = runPbr(dir, {"accuracy", "--variants", "exact", "--scenes", "sphere-grid", "--size", "32x18",
                                    "--pair-size", "16384x16384", "--out-dir", dir.file("acc")},
                              "ulimit -v 6000000; ");
  CHECK(pairCost.exitCode == 1);
  checkOneLineNaming(pairCost, "--pair-size 16384x16384");
  // The CPU reference holds 40 bytes a pixel (10.7 GB at 16384x16384): checked as well before a ray is cast.
  const Run reference =
      runPbr(dir, {"reference", "--size", "16384x16384", "--hdr", dir.file("r.pfm")}, "ulimit -v 6000000; ");
  CHECK(reference.exitCode == 1);
  checkOneLineNaming(reference, "--size 16384x16384: the frame needs about 10.7 GB (40 bytes per pixel)");
  CHECK_FALSE(fs::exists(dir.file("r.pfm")));
  // pbr accuracy traces its reference frames at --size too (it failed with std::bad_alloc).
  const Run accuracy = runPbr(dir, {"accuracy", "--variants", "exact", "--scenes", "sphere-grid", "--size",
                                    "16384x16384", "--no-cost", "--out-dir", dir.file("acc2")},
                              "ulimit -v 6000000; ");
  CHECK(accuracy.exitCode == 1);
  checkOneLineNaming(accuracy, "--size 16384x16384: the frame needs about 10.7 GB (40 bytes per pixel)");
#endif
}

TEST_CASE("hostile outputs: the driver is asked about each target's format before anything is allocated") {
  PBR_REQUIRE_GL();
  pbr::RendererConfig wide;
  wide.gbuffer = pbr::GBufferPrecision::Float;
  wide.hdrFormat = pbr::HdrFormat::Rgba32f;
  CHECK_NOTHROW(pbr::checkFrameFormats(64, 32, "--size", pbr::frameFormats(wide)));
  GLint maxSize = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
  // Over GL_MAX_TEXTURE_SIZE every driver's proxy test fails; the first format asked about is named.
  const std::string size = "--pair-size " + std::to_string(maxSize + 1) + "x1";
  CHECK_THROWS_WITH(pbr::checkFrameFormats(maxSize + 1, 1, "--pair-size", pbr::frameFormats(wide)),
                    (size + ": the OpenGL driver refuses RGBA32F textures of that size (proxy texture test); try a "
                            "smaller size").c_str());
  // llvmpipe caps one texture at 1 GiB: 16384 x 16384 passes GL_MAX_TEXTURE_SIZE and, on a large machine, the
  // memory estimate, but not the RGBA16F HDR target (2 GiB). Refused by name within a second, not after minutes.
  const std::string renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  if (renderer.find("llvmpipe") != std::string::npos) {
    const TempDir dir;
    const Run huge = runPbr(dir, tinyRender({"--size", "16384x16384"}));
    CHECK(huge.exitCode == 1);
    checkOneLineNaming(huge, "--size 16384x16384: ");
    checkNotRendered(huge);
  }
}

TEST_CASE("hostile outputs: an environment wider than the context's textures fails naming the file and the limit") {
  PBR_REQUIRE_GL();
  const TempDir dir;
  // 16385 flat pixels of one row: readable, but one pixel past llvmpipe's 16384 a side.
  std::string hdr = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 16385\n";
  for (int i = 0; i < 16385; ++i) hdr += std::string("\x80\x80\x80\x81", 4);
  const std::string wide = dir.write("wide.hdr", hdr);
  const Run run = runPbr(dir, tinyRender({"--environment", wide}));
  CHECK(run.exitCode == 1);
  checkOneLineNaming(run, wide + ": 16385x1 pixels, over the OpenGL limit of");
  CHECK(run.err.find("GL_MAX_TEXTURE_SIZE") != std::string::npos);
  checkNotRendered(run);
}

TEST_CASE("hostile outputs: a directory as an environment fails with exit 1 naming it") {
  PBR_REQUIRE_GL();
  const TempDir dir;
  const fs::path envs = dir.path() / "envs.hdr";
  fs::create_directories(envs);
  const Run option = runPbr(dir, tinyRender({"--environment", envs.string()}));
  CHECK(option.exitCode == 1);
  checkOneLineNaming(option, envs.string() + ": not a regular file (a directory)");
  checkNotRendered(option);

  const std::string scene = dir.write(
      "s.json", R"({"camera": {"position": [0, 2, 5], "target": [0, 0, 0]}, "environment": {"file": "envs.hdr"},
                    "objects": [{"shape": "sphere"}]})");
  const Run json = runPbr(dir, tinyRender({"--scene", scene}));
  CHECK(json.exitCode == 1);
  checkOneLineNaming(json, envs.string());
  checkNotRendered(json);
}

TEST_CASE("hostile outputs: an output naming an input or another output is refused before any work, inputs unchanged") {
  const TempDir dir;
  const std::string scene = dir.write("s.json", R"({"camera": {"position": [0, 2, 5], "target": [0, 0, 0]},
    "objects": [{"shape": "sphere"}], "lights": [{"position": [1, 2, 2], "radius": 5, "luminous_power": 100}]})");
  const std::string text = readFile(scene);
  fs::create_symlink(scene, dir.file("link.json"));
  fs::create_hard_link(scene, dir.file("hard.json"));
  fs::create_symlink(scene, dir.file("link.pfm"));
  const auto refused = [&](const std::vector<std::string>& args, const std::string& line) {
    CAPTURE(line);
    const Run run = runPbr(dir, args);
    CHECK(run.exitCode == 2);
    checkOneLineNaming(run, line);
    CHECK(readFile(scene) == text);
  };
  // The scene under its own name, through a symbolic link and through a hard link.
  for (const char* json : {"s.json", "link.json", "hard.json"}) {
    refused({"render", "--size", "8x8", "--frames", "1", "--scene", scene, "--json", dir.file(json)},
            "--json " + dir.file(json) + ": the same file as --scene " + scene +
                ", which the command reads: writing it would replace it");
  }
  refused({"reference", "--scene", scene, "--size", "8x8", "--hdr", dir.file("link.pfm")},
          "--hdr " + dir.file("link.pfm") + ": the same file as --scene");
  // Two outputs of one command, and a merged report over one of its shards.
  refused({"bench", "--scene", "default", "--json", dir.file("a.json"), "--trace", dir.file("a.json")},
          "--trace " + dir.file("a.json") + ": the same file as --json " + dir.file("a.json") +
              ": one would replace the other");
  refused({"bench-merge", scene, dir.file("link.json"), "--json", dir.file("hard.json")},
          "--json " + dir.file("hard.json") + ": the same file as shard " + scene);
  CHECK(entries(dir.path()).size() == 6);  // the scene, its three links, stdout.txt and stderr.txt: nothing written
}

TEST_CASE("hostile outputs: a dangling symbolic link is kept, the file it names made") {
  PBR_REQUIRE_GL();
  const TempDir dir;
  fs::create_symlink("made/frame.png", dir.file("link.png"));
  const Run run = runPbr(dir, tinyRender({"--out", dir.file("link.png")}));
  CHECK(run.exitCode == 0);
  CHECK(fs::is_symlink(fs::symlink_status(dir.file("link.png"))));
  CHECK(fs::is_regular_file(dir.path() / "made" / "frame.png"));
  CHECK(pbr::readPng(dir.file("link.png")).width == 32);
}

TEST_CASE("hostile outputs: a render ended by SIGTERM leaves no temporary behind") {
  PBR_REQUIRE_GL();
  const TempDir dir;
  const fs::path folder = dir.path() / "out";
  fs::create_directories(folder);
  // The outputs are opened (as temporaries) before the first frame; the shell waits for one, then ends the run.
  std::string command = "cd " + dir.path().string() + "; " + std::string(PBR_BINARY) +
                        " render --size 64x36 --warmup 0 --frames 100000 --hdr out/f.pfm >/dev/null 2>&1 & pid=$!; "
                        "for i in $(seq 200); do ls out/.f.pfm.* >/dev/null 2>&1 && break; sleep 0.05; done; "
                        "ls out/.f.pfm.* >/dev/null 2>&1 && echo seen > seen.txt; kill -TERM $pid; wait $pid";
  const int status = std::system(command.c_str());
  CHECK(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 128 + SIGTERM);  // ended by the signal, as before
  CHECK(fs::exists(dir.path() / "seen.txt"));
  CHECK(entries(folder).empty());
}


TEST_CASE("render notes: a scene wholly out of view and a frame that clips to white are named") {
  PBR_REQUIRE_GL();
  const TempDir dir;
  // A floor filling the view from above, lit by a sun; then the same floor 500 m behind the camera.
  const auto scene = [&](const std::string& name, double floorY) {
    return dir.write(name, R"({"camera": {"position": [0, 3, 0], "target": [0, 0, 0], "up": [0, 0, -1]},
      "objects": [{"shape": "plane", "transform": {"translate": [0, )" + std::to_string(floorY) + R"(, 0], "scale": 40}}],
      "lights": [{"type": "directional", "direction": [0, -1, 0], "illuminance_lux": 2}]})");
  };
  const auto notesOf = [&](const std::vector<std::string>& extra) {
    std::vector<std::string> args = {"render", "--size", "32x18", "--frames", "1", "--warmup", "0"};
    args.insert(args.end(), extra.begin(), extra.end());
    const Run run = runPbr(dir, args);
    CHECK(run.exitCode == 0);
    std::vector<std::string> notes;
    std::istringstream lines(run.out);
    for (std::string line; std::getline(lines, line);) {
      if (line.rfind("note: ", 0) == 0) notes.push_back(line);
    }
    return notes;
  };
  const std::string floor = scene("floor.json", 0.0);
  CHECK(notesOf({"--scene", floor, "--out", dir.file("a.png")}).empty());
  CHECK(notesOf({"--scene", floor, "--exposure", "1e6", "--out", dir.file("b.png")}) ==
        std::vector<std::string>{"note: 100.0% of the frame clips to white: an exposure of 1e+06 is too high for this "
                                 "scene (--exposure, --ev100); --exposure auto meters it from the frame"});
  CHECK(notesOf({"--scene", scene("behind.json", 500.0)}) ==
        std::vector<std::string>{"note: no object of the scene lies in the camera's view (between its near and far "
                                 "planes): the frame shows the background alone"});
}
