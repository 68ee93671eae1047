#include <cstdio>
#include <iostream>
#include <optional>

#include "app/args.hpp"
#include "app/bench/chart_script.hpp"
#include "app/commands.hpp"
#include "app/option_table.hpp"
#include "app/common_options.hpp"
#include "app/experiments/experiments.hpp"
#include "app/scene_source.hpp"
#include "core/gl/context.hpp"
#include "core/io/image_output.hpp"
#include "core/io/output_file.hpp"

namespace pbr {

namespace {

void printTable(const ExperimentTable& t) {
  std::printf("%-16s", t.xLabel.c_str());
  for (const std::string& c : t.columns) std::printf(" %22s", c.c_str());
  std::printf("\n");
  for (size_t i = 0; i < t.x.size(); ++i) {
    std::printf("%-16g", t.x[i]);
    for (double v : t.rows[i]) std::printf(" %22.6g", v);
    std::printf("\n");
  }
}

void writeChart(const std::string& csv, const std::string& png, const ExperimentResult& r) {
  std::vector<std::string> args = {csv, png, "--title", r.chartTitle, "--ylabel", r.yLabel};
  if (r.logX) args.push_back("--logx");
  if (r.logY) args.push_back("--logy");
  if (!runChartScript("plot_csv.py", args)) {
    throw std::runtime_error(png + ": the chart could not be drawn (scripts/plot_csv.py needs python3-matplotlib)");
  }
}

}  // namespace

int runExperiment(const std::vector<std::string>& argv) {
  const auto& specs = commandOptions(Command::Experiment);
  const bool wantsHelp = argv.empty() || argv[0] == "--help" || argv[0] == "-h";
  if (wantsHelp) {
    std::cout << Args::helpText("pbr experiment NAME [options]",
                                "Reproduces a Blinn-Phong vs PBR comparison; NAME is one of:\n"
                                "  fresnel     specular reflectance of a floor at view angles 0, 40, 65, 80 "
                                "degrees; --size made odd\n"
                                "  saturation  fully saturated pixels of a wall under 1..10 co-located lights\n"
                                "  triangles   frame time of both models under 100 lights as triangles grow; "
                                "--frames each, after a warm-up\n"
                                "  tonemap     every tone curve: a grey ramp's display values, and one frame of "
                                "--scene side by side",
                                specs);
    return argv.empty() ? 2 : 0;
  }
  const std::string name = argv[0];
  if (name != "fresnel" && name != "saturation" && name != "triangles" && name != "tonemap") {
    throw UsageError("unknown experiment '" + name + "' (expected fresnel, saturation, triangles or tonemap)");
  }
  Args args(specs, std::vector<std::string>(argv.begin() + 1, argv.end()));
  if (args.helpRequested()) return runExperiment({"--help"});
  const std::string outDir = args.get("--out-dir");
  const glm::ivec2 size = args.getSize("--size");
  const int frames = args.getInt("--frames", 1, 1000);
  const EglPlatform platform = parseEglPlatform(args.get("--egl-platform"));

  std::optional<Scene> scene;
  if (name == "tonemap") {
    scene = resolveScene(args.get("--scene"), SceneParams{});
  } else if (args.has("--scene")) {
    throw UsageError("--scene applies only to the tonemap experiment");
  }
  makeOutputFolder("--out-dir", outDir);  // before the experiment runs, so that a bad folder fails at once
  auto context = createHeadlessContext(platform);
  std::printf("renderer: %s | %s | %s\n", context->info().renderer.c_str(), context->info().version.c_str(),
              context->info().platform.c_str());
  const ShaderLibrary shaders;
  const ExperimentResult result = name == "fresnel"      ? runFresnelExperiment(shaders, size)
                                  : name == "saturation" ? runSaturationExperiment(shaders, size)
                                  : name == "tonemap"    ? runToneMapExperiment(shaders, size, *scene)
                                                         : runTrianglesExperiment(shaders, size, frames);
  for (const ExperimentImage& img : result.images) writePng(outDir + "/" + img.file, img.image);
  const std::string csv = outDir + "/" + name + ".csv", png = outDir + "/" + name + ".png";
  writeExperimentCsv(csv, result.table);
  writeChart(csv, png, result);
  printTable(result.table);
  std::printf("wrote %s, %s and %zu images in %s\n", csv.c_str(), png.c_str(), result.images.size(), outDir.c_str());
  return 0;
}

}  // namespace pbr
