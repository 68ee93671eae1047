#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "app/accuracy_metrics.hpp"
#include "app/accuracy_variants.hpp"
#include "app/args.hpp"
#include "app/chart_script.hpp"
#include "app/brdf_slice.hpp"
#include "app/commands.hpp"
#include "app/error_map.hpp"
#include "app/frame_stats.hpp"
#include "app/offscreen.hpp"
#include "core/context.hpp"

namespace pbr {

namespace {

const std::vector<OptionSpec>& accuracyOptions() {
  static const std::vector<OptionSpec> specs = {
      {"--scenes", "LIST",
       "comma-separated scenes of analytic shapes; fresnel-floor:DEG sets the view angle (default sphere-grid,"
       "fresnel-floor:0,fresnel-floor:40,fresnel-floor:65,fresnel-floor:80); textures are removed"},
      {"--variants", "LIST", "comma-separated variants or all (default): exact, exact-rgba32f, default, hammon, "
                             "separable, beckmann, lambert, burley, schlick-sg, lambert-1-f-vh, study, "
                             "r11g11b10f, gbuffer-float, fast, blinn-phong"},
      {"--size", "WxH", "frame size in pixels (default 160x90)"},
      {"--frames", "K", "warm frames timed per variant and scene, after 1 warm-up (default 3)"},
      {"--out-dir", "DIR", "where accuracy.csv, accuracy.png and the error maps go (default out/accuracy)"},
      {"--slices", "", "also write per-variant BRDF error slices over (n.v angle) x (roughness)"},
      {"--slice-size", "AxR", "slice grid: view angles x roughness values (default 90x64)"},
      {"--no-chart", "", "skip the chart (drawn by scripts/plot_accuracy.py with python3-matplotlib)"},
      {"--threads", "N", "reference renderer threads, 0 for all (default 0)"},
      {"--timing", "MODE", "auto (default), gpu (timer queries) or serial (glFinish + CPU clock)"},
      {"--egl-platform", "P", "auto (default), surfaceless (Mesa) or device (first hardware device)"},
  };
  return specs;
}

std::vector<std::string> splitList(const std::string& list) {
  std::vector<std::string> out;
  std::stringstream in(list);
  for (std::string item; std::getline(in, item, ',');)
    if (!item.empty()) out.push_back(item);
  return out;
}

void writeSlices(const ShaderLibrary& shaders, const std::vector<AccuracyVariant>& variants, glm::ivec2 grid,
                 const std::filesystem::path& dir) {
  std::ofstream csv(dir / "slices.csv");
  csv << "variant,material,max_relative_error,angle_deg_of_max,roughness_of_max,mean_relative_error\n";
  const std::pair<const char*, SliceMaterial> materials[] = {{"dielectric", {glm::vec3(0.8f), 0.0f}},
                                                             {"metal", {glm::vec3(0.95f, 0.64f, 0.54f), 1.0f}}};
  std::vector<ShadingVariant> done;
  for (const AccuracyVariant& v : variants) {
    // Blinn-Phong is no normalised BRDF, and HDR formats do not change the BRDF: one slice per term choice.
    if (v.model != ShadingModel::Pbr || std::find(done.begin(), done.end(), v.shading) != done.end()) continue;
    done.push_back(v.shading);
    for (const auto& [materialName, material] : materials) {
      const BrdfSlice s = computeBrdfSlice(shaders, v.shading, material, grid.x, grid.y);
      double sum = 0.0, worst = -1.0;
      int wa = 0, wr = 0;
      for (int r = 0; r < s.roughnesses; ++r)
        for (int a = 0; a < s.angles; ++a) {
          sum += s.at(a, r);
          if (s.at(a, r) > worst) worst = s.at(a, r), wa = a, wr = r;
        }
      csv << v.name << ',' << materialName << ',' << worst << ',' << (wa + 0.5) * 90.0 / s.angles << ','
          << (wr + 0.5) / s.roughnesses << ',' << sum / s.relativeError.size() << '\n';
      const std::string png = (dir / ("slice-" + v.name + "-" + materialName + ".png")).string();
      writePng(png, errorMapImage(s.relativeError, s.angles, s.roughnesses, 1e-4, 10.0));
      std::printf("slice %-14s %-10s max relative error %.3g at %.1f deg, roughness %.2f -> %s\n", v.name.c_str(),
                  materialName, worst, (wa + 0.5) * 90.0 / s.angles, (wr + 0.5) / s.roughnesses, png.c_str());
    }
  }
}

}  // namespace

int runAccuracy(const std::vector<std::string>& argv) {
  const auto& specs = accuracyOptions();
  Args args(specs, argv);
  if (args.helpRequested()) {
    std::cout << Args::helpText("pbr accuracy [options]",
                                "Renders scenes with each shading variant, compares them with the CPU reference "
                                "and writes a CSV (lighting time and error per variant and scene), a time-vs-error "
                                "chart and per-pixel error maps (log10 relative error, colour scale below).",
                                specs);
    return 0;
  }
  const std::vector<AccuracyVariant> variants = selectVariants(args.get("--variants", "all"));
  const std::vector<std::string> sceneSpecs =
      splitList(args.get("--scenes", "sphere-grid,fresnel-floor:0,fresnel-floor:40,fresnel-floor:65,fresnel-floor:80"));
  if (sceneSpecs.empty()) throw UsageError("--scenes lists no scene");
  const glm::ivec2 size = args.getSize("--size", {160, 90});
  const int frames = args.getInt("--frames", 3, 1, 1000);
  const std::filesystem::path dir = args.get("--out-dir", "out/accuracy");
  const bool slices = args.has("--slices");
  const glm::ivec2 sliceGrid = args.getSize("--slice-size", {90, 64});
  reference::ReferenceOptions referenceOptions;
  referenceOptions.threads = args.getInt("--threads", 0, 0, 1024);
  const std::string timing = args.get("--timing", "auto");
  const EglPlatform platform = parseEglPlatform(args.get("--egl-platform", "auto"));
  chooseTimingMode(timing, "");
  std::vector<AccuracyScene> scenes;
  for (const std::string& spec : sceneSpecs) scenes.push_back(loadAccuracyScene(spec));

  auto context = createHeadlessContext(platform);
  const ContextInfo& info = context->info();
  const TimingMode mode = chooseTimingMode(timing, info.renderer);
  std::printf("renderer: %s | timing: %s, median of %d warm frames\n", info.renderer.c_str(), describe(mode), frames);
  std::filesystem::create_directories(dir);
  const ShaderLibrary shaders;

  const std::string csvPath = (dir / "accuracy.csv").string();
  std::ofstream csv(csvPath);
  if (!csv) throw std::runtime_error(csvPath + ": cannot write");
  csv << "variant,scene,model,terms,hdr_format,gbuffer,lighting_ms,relative_rmse,mean_levels,max_levels,share_over_2,"
         "pixels\n";
  std::printf("%-14s %-18s %10s %10s %8s %6s %8s\n", "variant", "scene", "light ms", "rel RMSE", "mean lv", "max",
              ">2 lv");
  for (const AccuracyScene& s : scenes) {
    const reference::ReferenceFrame ref = reference::renderReference(s.scene, size.x, size.y, referenceOptions);
    const ImageRgba8 refLdr = postProcessReference(shaders, ref.radiance, s.scene.exposure);
    for (const AccuracyVariant& v : variants) {
      FrameOptions options;
      options.model = v.model;
      options.variant = v.shading;
      options.exposure = s.scene.exposure;
      RendererConfig config;
      config.hdrFormat = v.hdr;
      config.gbuffer = v.gbuffer;
      const RenderedFrames f = renderOffscreen(shaders, s.scene, size, options, frames + 1, config, mode);
      const std::vector<FrameTiming> warm(f.timings.begin() + 1, f.timings.end());
      double lightingMs = 0.0;
      for (const PassTiming& p : medianPassTimes(warm))
        if (p.name == "lighting") lightingMs = p.ms;
      const ErrorMetrics m = measureError(f.hdr, f.ldr, ref, refLdr);
      csv << v.name << ',' << s.label << ',' << toString(v.model) << ",\""
          << (v.model == ShadingModel::Pbr ? toString(v.shading) : "") << "\"," << toString(v.hdr) << ',' << toString(v.gbuffer) << ','
          << lightingMs << ',' << m.relativeRmse << ',' << m.meanLevels << ',' << m.maxLevels << ',' << m.shareOver2
          << ',' << m.pixels << '\n';
      std::printf("%-14s %-18s %10.3f %10.4g %8.3f %6.0f %8.4f\n", v.name.c_str(), s.label.c_str(), lightingMs,
                  m.relativeRmse, m.meanLevels, m.maxLevels, m.shareOver2);
      writePng((dir / ("error-" + v.name + "-" + s.label + ".png")).string(),
               errorMapImage(relativeErrorPerPixel(f.hdr, ref), size.x, size.y, 1e-4, 1.0));
    }
  }
  csv.close();
  std::printf("wrote %s and error maps error-VARIANT-SCENE.png in %s\n", csvPath.c_str(), dir.string().c_str());
  if (slices) writeSlices(shaders, variants, sliceGrid, dir);
  checkGlError("accuracy");
  if (!args.has("--no-chart")) {
    const std::string png = (dir / "accuracy.png").string();
    // The CSV is the result; a machine without matplotlib still gets it.
    if (runChartScript("plot_accuracy.py", {csvPath, png})) std::printf("wrote %s\n", png.c_str());
    else std::fprintf(stderr, "pbr accuracy: chart skipped (scripts/plot_accuracy.py needs python3-matplotlib)\n");
  }
  return 0;
}

}  // namespace pbr
