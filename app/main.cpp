#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

#include "app/args.hpp"
#include "app/commands.hpp"
#include "core/gl/context.hpp"
#include "core/scene/messages.hpp"
#include "core/io/output_file.hpp"
#include "app/provenance.hpp"

namespace {

struct Command {
  const char* name;
  int (*run)(const std::vector<std::string>&);
  const char* summary;
};

const Command kCommands[] = {
    {"render", pbr::runRender, "render a scene headlessly, print per-pass timings, write PNG/EXR/PFM captures"},
    {"bench", pbr::runBench, "sweep light counts, culling and shading models; per-pass times as table, CSV, JSON, trace"},
    {"bench-merge", pbr::runBenchMerge, "join the JSON reports of a sweep's shards (bench --shard K/N) into one report"},
    {"experiment", pbr::runExperiment, "reproduce a Blinn-Phong vs PBR experiment: images, CSV and chart"},
    {"view", pbr::runView, "an interactive window: orbit camera, runtime model/culling/debug-view switches, live timings"},
    {"reference", pbr::runReference, "CPU ray-cast reference frame in double precision (meshes or exact shapes), EXR/PFM"},
    {"accuracy", pbr::runAccuracy, "shading variants against the CPU reference: time vs error CSV, chart, error maps"},
};

void printUsage(FILE* out) {
  std::fprintf(out, "usage: pbr <command> [options]\n\nA clustered deferred renderer (OpenGL 4.5, headless EGL).\n\ncommands:\n");
  for (const Command& c : kCommands) std::fprintf(out, "  %-11s %s\n", c.name, c.summary);
  std::fprintf(out, "\n'pbr <command> --help' describes a command's options; 'pbr --version' the build.\n");
}

}  // namespace

int main(int argc, char** argv) {
  pbr::removeTemporariesOnSignals();
  const std::vector<std::string> all(argv + 1, argv + argc);
  if (all.empty() || all[0] == "--help" || all[0] == "-h" || all[0] == "help") {
    printUsage(all.empty() ? stderr : stdout);
    return all.empty() ? 2 : 0;
  }
  if (all[0] == "--version") {
    std::printf("%s\n", pbr::versionLine().c_str());
    return 0;
  }
  for (const Command& c : kCommands) {
    if (all[0] != c.name) continue;
    const std::vector<std::string> rest(all.begin() + 1, all.end());
    try {
      return c.run(rest);
    } catch (const pbr::UsageError& e) {
      std::fprintf(stderr, "pbr %s: %s (see 'pbr %s --help')\n", c.name, pbr::oneLine(e.what()).c_str(), c.name);
      return 2;
    } catch (const std::invalid_argument& e) {
      std::fprintf(stderr, "pbr %s: %s (see 'pbr %s --help')\n", c.name, pbr::oneLine(e.what()).c_str(), c.name);
      return 2;
    } catch (const std::filesystem::filesystem_error& e) {
      // The library's text ("filesystem error: status: ... [path]") said as the other errors are: the file first.
      std::fprintf(stderr, "pbr %s: %s: %s\n", c.name, pbr::oneLine(e.path1().string()).c_str(),
                   e.code().message().c_str());
      return 1;
    } catch (const pbr::ContextError& e) {
      std::fprintf(stderr, "pbr %s: no OpenGL 4.5 context: %s\n", c.name, pbr::oneLine(e.what()).c_str());
      return 3;
    } catch (const std::exception& e) {
      std::fprintf(stderr, "pbr %s: %s\n", c.name, pbr::oneLine(e.what()).c_str());
      return 1;
    }
  }
  std::fprintf(stderr, "pbr: unknown command '%s' (see 'pbr --help')\n", pbr::oneLine(all[0].c_str()).c_str());
  return 2;
}
