#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <ostream>
#include <iostream>
#include <sstream>

#include "renderer/display_image.hpp"
#include "renderer/frame_limits.hpp"
#include "app/accuracy/accuracy_metrics.hpp"
#include "app/accuracy/accuracy_variants.hpp"
#include "app/accuracy/pair_cost.hpp"
#include "app/args.hpp"
#include "app/bench/bench_report.hpp"
#include "app/bench/chart_script.hpp"
#include "app/accuracy/brdf_slice.hpp"
#include "app/commands.hpp"
#include "app/option_table.hpp"
#include "app/common_options.hpp"
#include "app/accuracy/error_map.hpp"
#include "app/accuracy/shadow_cost.hpp"
#include "app/accuracy/shadow_comparison.hpp"
#include "app/accuracy/transparency_rows.hpp"
#include "renderer/offscreen.hpp"
#include "app/scene_source.hpp"
#include "core/gl/context.hpp"
#include "core/io/image_output.hpp"
#include "core/io/output_file.hpp"

namespace pbr {

namespace {

std::vector<std::string> splitList(const std::string& list) {
  std::vector<std::string> out;
  std::stringstream in(list);
  for (std::string item; std::getline(in, item, ',');)
    if (!item.empty()) out.push_back(item);
  return out;
}

// A shadow row's own CSV columns: its filter and atlas, pass times in ms (n/a without timings), the lit/shadowed
// state's misclassified share and the pixels it compared.
std::string shadowCells(const ShadowRow& row, const ShadowCost* c, const ShadowAgreement& agreement) {
  const bool shadowed = row.settings.mode != ShadowMode::None;
  std::string cells = std::string(shadowed ? toString(row.settings.filter) : "none") + ',' +
                      (shadowed ? std::to_string(row.settings.atlasSize) : "-");
  for (const double ms : {c ? c->shadowMs.median : 0.0, c ? c->lightingMs.median : 0.0, c ? c->passesMs.median : 0.0,
                          c ? c->passesMs.p10 : 0.0, c ? c->passesMs.p90 : 0.0})
    cells += ',' + (c ? fixedDecimals(ms, 3) : std::string("n/a"));
  return cells + ',' + fixedDecimals(agreement.misclassifiedShare(), 5) + ',' + std::to_string(agreement.compared);
}

// A transparency row's own CSV columns: its ordering, then the transparency pass's and the frame's ms, median, p10
// and p90 (n/a without timings).
std::string transparencyCells(const TransparencyRow& row, const TransparencyCost* c) {
  std::string cells = toString(row.transparency);
  if (!c) return cells + ",n/a,n/a,n/a,n/a,n/a,n/a";
  for (const TimeSummary& t : {c->transparencyMs, c->frameMs}) {
    for (const double ms : {t.median, t.p10, t.p90}) cells += ',' + fixedDecimals(ms, 3);
  }
  return cells;
}

// "median (p10-p90)" of `t` in ms, "-" without timings.
std::string msSpread(const TimeSummary* t) {
  return t ? fixedDecimals(t->median, 2) + " (" + fixedDecimals(t->p10, 2) + "-" + fixedDecimals(t->p90, 2) + ")"
           : std::string("-");
}

void writeSlices(const ShaderLibrary& shaders, const std::vector<AccuracyVariant>& variants, glm::ivec2 grid,
                 const std::filesystem::path& dir) {
  OutputFile csvFile((dir / "slices.csv").string());
  std::ostream& csv = csvFile.stream();
  csv << "variant,material,max_relative_error,angle_deg_of_max,roughness_of_max,mean_relative_error\n";
  const std::pair<const char*, SliceMaterial> materials[] = {{"dielectric", {glm::vec3(0.8f), 0.0f}},
                                                             {"metal", {glm::vec3(0.95f, 0.64f, 0.54f), 1.0f}}};
  std::vector<ShadingVariant> done;
  for (const AccuracyVariant& v : variants) {
    // Blinn-Phong is no normalised BRDF, and HDR formats do not change the BRDF: one slice per term choice.
    if (v.model() != ShadingModel::Pbr || std::find(done.begin(), done.end(), v.shading()) != done.end()) continue;
    done.push_back(v.shading());
    for (const auto& [materialName, material] : materials) {
      const BrdfSlice s = computeBrdfSlice(shaders, v.shading(), material, grid.x, grid.y);
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
  csvFile.commit();
}

// What pbr accuracy was asked to measure, read and checked before a context is made.
struct AccuracyRequest {
  std::vector<AccuracyVariant> variants;
  std::vector<AccuracyScene> scenes;
  std::vector<ShadowRow> shadowRows;
  AccuracyScene shadowScene;
  glm::ivec2 shadowCostSize{0};
  std::vector<TransparencyRow> transparencyRows;
  AccuracyScene transparencyScene;
  glm::ivec2 transparencyCostSize{0};
  glm::ivec2 size{0};
  // The display transform of every compared 8-bit frame, the reference's and the variants' alike: the error in
  // levels is the error a viewer with this curve would see.
  ToneCurve curve = ToneCurve::AcesHill;
  PairCostSettings cost;
  bool measureCost = true;
  std::filesystem::path dir;
  bool slices = false;
  glm::ivec2 sliceGrid{0};
  reference::ReferenceOptions referenceOptions;
  std::string timing;
  EglPlatform platform = EglPlatform::Auto;
};

AccuracyRequest readRequest(const Args& args) {
  AccuracyRequest r;
  r.variants = selectVariants(args.get("--variants"));
  r.shadowRows = parseShadowRows(args.get("--shadow-rows"));
  r.shadowCostSize = args.getSize("--shadow-cost-size");
  r.transparencyRows = parseTransparencyRows(args.get("--transparency-rows"));
  r.transparencyCostSize = args.getSize("--transparency-cost-size");
  const std::vector<std::string> sceneSpecs = splitList(args.get("--scenes"));
  if (sceneSpecs.empty()) throw UsageError("--scenes lists no scene");
  r.size = args.getSize("--size");
  r.curve = readToneCurve(args);
  // The reference frames at --size (40 bytes a pixel, as pbr reference holds them) before any is traced; the GPU
  // frames are checked by their renderer.
  checkFrameSize(r.size.x, r.size.y, "--size", 40, {kMaxSizeSide, availableMemoryBytes()});
  r.cost.size = args.getSize("--pair-size");
  r.cost.sizeOption = "--pair-size";
  r.cost.lights = args.getInt("--pair-lights", 1, 1 << 16);
  r.cost.rounds = args.getInt("--rounds", 1, 10000);
  r.measureCost = !args.has("--no-cost");
  r.dir = args.get("--out-dir");
  r.slices = args.has("--brdf-slices");
  r.sliceGrid = args.getSize("--brdf-slice-size");
  r.referenceOptions.threads = args.getInt("--threads", 0, 1024);
  r.timing = args.get("--timing");
  r.platform = parseEglPlatform(args.get("--egl-platform"));
  chooseTimingMode(r.timing, "");
  for (const std::string& spec : sceneSpecs) r.scenes.push_back(loadAccuracyScene(spec, sceneFileParams(args)));
  r.shadowScene = loadAccuracyScene(args.get("--shadow-scene"), sceneFileParams(args));
  r.transparencyScene = loadAccuracyScene(args.get("--transparency-scene"), sceneFileParams(args));
  if (!r.transparencyRows.empty() && !hasBlendMaterial(r.transparencyScene.scene))
    throw UsageError("--transparency-scene " + args.get("--transparency-scene") +
                     ": the scene has no BLEND material for the transparency rows to measure (--transparency-rows "
                     "none for no rows)");
  return r;
}

// The timings: each variant's cost per pair, and the shadow and transparency rows' pass times; empty with --no-cost.
struct AccuracyCosts {
  std::vector<PairCost> pairs;
  std::vector<ShadowCost> shadows;
  std::vector<TransparencyCost> transparency;
};

AccuracyCosts measureCosts(const ShaderLibrary& shaders, const AccuracyRequest& r, TimingMode mode) {
  AccuracyCosts costs;
  if (!r.measureCost) return costs;
  PairCostSettings cost = r.cost;
  cost.timing = mode;
  std::printf("cost per light-pixel pair: %dx%d, %d lights reaching every pixel, brute force, %d rounds%s\n",
              cost.size.x, cost.size.y, cost.lights, cost.rounds,
              mode == TimingMode::Serializing ? " (CPU-rasterizer figures where the renderer is llvmpipe)" : "");
  std::vector<PairCostVariant> costVariants;
  for (const AccuracyVariant& v : r.variants) costVariants.push_back(pairCostVariant(v));
  costs.pairs = measurePairCost(shaders, costVariants, cost);
  if (!r.shadowRows.empty()) {
    std::printf("shadow rows' passes: %s at %dx%d, %d rounds\n", r.shadowScene.label.c_str(), r.shadowCostSize.x,
                r.shadowCostSize.y, cost.rounds);
    std::vector<FrameOptions> options;
    for (const ShadowRow& row : r.shadowRows) options.push_back(shadowRowOptions(row, r.shadowScene.scene));
    costs.shadows = measureShadowCost(shaders, r.shadowScene.scene, r.shadowCostSize, exactVariantConfig(), options,
                                      cost.rounds, mode);
  }
  if (!r.transparencyRows.empty()) {
    std::printf("transparency rows' passes: %s at %dx%d, %d rounds\n", r.transparencyScene.label.c_str(),
                r.transparencyCostSize.x, r.transparencyCostSize.y, cost.rounds);
    costs.transparency = measureTransparencyCost(shaders, r.transparencyScene.scene, r.transparencyCostSize,
                                                 r.transparencyRows, cost.rounds, mode);
  }
  return costs;
}

// The CSV's circumstances, beside it (csv_provenance.hpp).
KeyValues csvProvenance(const AccuracyRequest& r, const ContextInfo& info, TimingMode mode) {
  KeyValues provenance = {
      {"gl_renderer", info.renderer},
      {"timing_mode", describe(mode)},
      {"pair_cost_frame", sizeText(r.cost.size) + ", " + std::to_string(r.cost.lights) +
                              " lights reaching every pixel, brute force, " + std::to_string(r.cost.rounds) +
                              " rounds"},
      {"compared_frame", sizeText(r.size)},
      {"tone_curve", toString(r.curve)}};
  if (!r.shadowRows.empty()) {
    provenance.push_back({"shadow_cost_frame", r.shadowScene.label + ", " + sizeText(r.shadowCostSize) +
                                                   ", shadow and lighting passes, " + std::to_string(r.cost.rounds) +
                                                   " rounds"});
    provenance.push_back({"shadow_state", "each casting light alone, lit where shadowed over unshadowed radiance >= "
                                          "0.5, against the reference's shadow rays; pixels within " +
                                              std::to_string(kShadowBandPx) +
                                              " px of a change of the reference's state are not compared"});
  }
  if (!r.transparencyRows.empty()) {
    provenance.push_back({"transparency_cost_frame", r.transparencyScene.label + ", " +
                                                         sizeText(r.transparencyCostSize) +
                                                         ", transparency pass and frame, " +
                                                         std::to_string(r.cost.rounds) + " rounds"});
    provenance.push_back({"transparency_rows", "the exact variant without shadows, GPU and reference"});
  }
  return provenance;
}

// The CSV and the table printed as it fills: a row per variant and scene (and the geometry row), per shadow row and
// per transparency row. Each row kind has no columns of the others, and the geometry, shadow and transparency rows
// no cost per pair: "n/a" in the CSV ("-" for the settings), "-" in the table.
class AccuracyTable {
 public:
  explicit AccuracyTable(std::ostream& csv) : csv_(csv) {
    csv_ << "variant,scene,model,terms,hdr_format,gbuffer,ns_per_pair_median,ns_per_pair_p10,ns_per_pair_p90,"
            "fixed_share,relative_rmse,mean_levels,max_levels,share_over_2,pixels,shadow_filter,shadow_atlas,"
            "shadow_ms_median,lighting_ms_median,passes_ms_median,passes_ms_p10,passes_ms_p90,misclassified_share,"
            "shadow_pixels,transparency,transparency_ms_median,transparency_ms_p10,transparency_ms_p90,"
            "frame_ms_median,frame_ms_p10,frame_ms_p90\n";
    std::printf("%-16s %-22s %9s %17s %10s %8s %6s %8s\n", "variant", "scene", "ns/pair", "p10-p90", "rel RMSE",
                "mean lv", "max", ">2 lv");
  }

  // A variant's row, or with `terms` of the reference the geometry row (no variant, no cost).
  void variantRow(const std::string& name, const std::string& scene, const std::string& model,
                  const std::string& terms, const std::string& hdr, const std::string& gbuffer, const PairCost* c,
                  const ErrorMetrics& m) {
    writeCsvRow(name, scene, model, terms, hdr, gbuffer, c, m, kNoShadowCells, kNoTransparencyCells);
    const std::string perPair = c ? fixedDecimals(c->nsPerPair.median, 3) : "-";
    const std::string spread =
        c ? fixedDecimals(c->nsPerPair.p10, 3) + "-" + fixedDecimals(c->nsPerPair.p90, 3) : std::string("-");
    std::printf("%-16s %-22s %9s %17s %10.4g %8.3f %6.0f %8.4f\n", name.c_str(), scene.c_str(), perPair.c_str(),
                spread.c_str(), m.relativeRmse, m.meanLevels, m.maxLevels, m.shareOver2);
  }

  void shadowHeader() {
    std::printf("\n%-20s %-12s %11s %12s %17s %10s %13s %8s\n", "shadow row", "scene", "shadow ms", "lighting ms",
                "both (p10-p90)", "rel RMSE", "misclassified", "pixels");
  }
  void shadowRow(const ShadowRow& row, const std::string& scene, const ShadowCost* c, const ShadowRowResult& r) {
    const AccuracyVariant& exact = exactVariant();
    writeCsvRow(row.name, scene, toString(exact.model()), describeTerms(exact.model(), exact.shading()),
                toString(exact.hdr()), toString(exact.gbuffer()), nullptr, r.error, shadowCells(row, c, r.agreement),
                kNoTransparencyCells);
    const std::string shadowMs = c ? fixedDecimals(c->shadowMs.median, 2) : "-";
    const std::string lightingMs = c ? fixedDecimals(c->lightingMs.median, 2) : "-";
    const std::string both = msSpread(c ? &c->passesMs : nullptr);
    std::printf("%-20s %-12s %11s %12s %17s %10.4g %12.3f%% %8zu\n", row.name.c_str(), scene.c_str(),
                shadowMs.c_str(), lightingMs.c_str(), both.c_str(), r.error.relativeRmse,
                100.0 * r.agreement.misclassifiedShare(), r.agreement.compared);
  }

  void transparencyHeader() {
    std::printf("\n%-20s %-12s %25s %22s %10s %8s %6s %8s\n", "transparency row", "scene",
                "transparency ms (p10-p90)", "frame ms (p10-p90)", "rel RMSE", "mean lv", "max", ">2 lv");
  }
  void transparencyRow(const TransparencyRow& row, const std::string& scene, const TransparencyCost* c,
                       const TransparencyRowResult& r) {
    const AccuracyVariant& exact = exactVariant();
    writeCsvRow(row.name, scene, toString(exact.model()), describeTerms(exact.model(), exact.shading()),
                toString(exact.hdr()), toString(exact.gbuffer()), nullptr, r.error, kNoShadowCells,
                transparencyCells(row, c));
    std::printf("%-20s %-12s %25s %22s %10.4g %8.3f %6.0f %8.4f\n", row.name.c_str(), scene.c_str(),
                msSpread(c ? &c->transparencyMs : nullptr).c_str(), msSpread(c ? &c->frameMs : nullptr).c_str(),
                r.error.relativeRmse, r.error.meanLevels, r.error.maxLevels, r.error.shareOver2);
  }

 private:
  static constexpr const char* kNoShadowCells = "-,-,n/a,n/a,n/a,n/a,n/a,n/a,n/a";
  static constexpr const char* kNoTransparencyCells = "-,n/a,n/a,n/a,n/a,n/a,n/a";

  void writeCsvRow(const std::string& name, const std::string& scene, const std::string& model,
                   const std::string& terms, const std::string& hdr, const std::string& gbuffer, const PairCost* c,
                   const ErrorMetrics& m, const std::string& shadowCells, const std::string& transparencyCells) {
    const auto cell = [&](double v, int decimals) { return c ? fixedDecimals(v, decimals) : std::string("n/a"); };
    csv_ << name << ',' << scene << ',' << model << ",\"" << terms << "\"," << hdr << ',' << gbuffer << ','
         << cell(c ? c->nsPerPair.median : 0, 4) << ',' << cell(c ? c->nsPerPair.p10 : 0, 4) << ','
         << cell(c ? c->nsPerPair.p90 : 0, 4) << ',' << cell(c ? c->fixedShare : 0, 4) << ',' << m.relativeRmse
         << ',' << m.meanLevels << ',' << m.maxLevels << ',' << m.shareOver2 << ',' << m.pixels << ','
         << shadowCells << ',' << transparencyCells << '\n';
  }

  std::ostream& csv_;
};

// Every scene against its reference: the geometry row where the scene is of analytic shapes, then each variant,
// with its error map.
void compareVariants(const ShaderLibrary& shaders, const AccuracyRequest& r, const AccuracyCosts& costs,
                     TimingMode mode, AccuracyTable& table) {
  for (const AccuracyScene& s : r.scenes) {
    reference::ReferenceOptions refOptions = r.referenceOptions;  // meshes; the geometry row switches a copy
    const reference::ReferenceFrame ref = reference::renderReference(s.scene, r.size.x, r.size.y, refOptions);
    const ImageRgba8 refLdr = displayImage(shaders, ref.radiance, s.scene.displayExposure(), r.curve);
    // The tessellation's own error: the same reference shading on the exact shapes the meshes approximate.
    if (hasOnlyAnalyticShapes(s.scene)) {
      refOptions.geometry = reference::Geometry::Analytic;
      const reference::ReferenceFrame exact = reference::renderReference(s.scene, r.size.x, r.size.y, refOptions);
      const ImageRgba8 exactLdr = displayImage(shaders, exact.radiance, s.scene.displayExposure(), r.curve);
      table.variantRow("geometry", s.label, "reference", "triangle meshes against the exact shapes", "-", "-",
                       nullptr, measureError(ref.radiance, refLdr, exact, exactLdr));
    }
    for (size_t i = 0; i < r.variants.size(); ++i) {
      const AccuracyVariant& v = r.variants[i];
      FrameOptions options = v.settings.frame;
      options.exposure = s.scene.displayExposure();
      options.toneCurve = r.curve;
      const RenderedFrames f = renderOffscreen(shaders, s.scene, r.size, options, 3, v.settings.renderer, mode);
      table.variantRow(v.name, s.label, toString(v.model()), describeTerms(v.model(), v.shading()),
                       toString(v.hdr()), toString(v.gbuffer()), costs.pairs.empty() ? nullptr : &costs.pairs[i],
                       measureError(f.hdr, f.ldr, ref, refLdr));
      writePng((r.dir / ("error-" + v.name + "-" + s.label + ".png")).string(),
               errorMapImage(relativeErrorPerPixel(f.hdr, ref), r.size.x, r.size.y, 1e-4, 1.0));
    }
  }
}

void compareShadowRows(const ShaderLibrary& shaders, const AccuracyRequest& r, const AccuracyCosts& costs,
                       TimingMode mode, AccuracyTable& table) {
  if (r.shadowRows.empty()) return;
  table.shadowHeader();
  const ShadowComparison comparison(shaders, r.shadowScene.scene, r.size, r.referenceOptions, mode, r.curve);
  for (size_t i = 0; i < r.shadowRows.size(); ++i) {
    const ShadowRow& row = r.shadowRows[i];
    const ShadowRowResult result = comparison.measure(row);
    table.shadowRow(row, r.shadowScene.label, costs.shadows.empty() ? nullptr : &costs.shadows[i], result);
    writePng((r.dir / ("error-" + row.name + "-" + r.shadowScene.label + ".png")).string(),
             errorMapImage(result.relativeError, r.size.x, r.size.y, 1e-4, 1.0));
  }
}

void compareTransparencyRows(const ShaderLibrary& shaders, const AccuracyRequest& r, const AccuracyCosts& costs,
                             TimingMode mode, AccuracyTable& table) {
  if (r.transparencyRows.empty()) return;
  table.transparencyHeader();
  const TransparencyComparison comparison(shaders, r.transparencyScene.scene, r.size, r.referenceOptions, mode,
                                          r.curve);
  for (size_t i = 0; i < r.transparencyRows.size(); ++i) {
    const TransparencyRow& row = r.transparencyRows[i];
    const TransparencyRowResult result = comparison.measure(row);
    const TransparencyCost* c = costs.transparency.empty() ? nullptr : &costs.transparency[i];
    table.transparencyRow(row, r.transparencyScene.label, c, result);
    writePng((r.dir / ("error-" + row.name + "-" + r.transparencyScene.label + ".png")).string(),
             errorMapImage(result.relativeError, r.size.x, r.size.y, 1e-4, 1.0));
  }
}

}  // namespace

int runAccuracy(const std::vector<std::string>& argv) {
  const auto& specs = commandOptions(Command::Accuracy);
  Args args(specs, argv);
  if (args.helpRequested()) {
    std::cout << Args::helpText("pbr accuracy [options]",
                                "Measures each shading variant's cost per light-pixel pair (brute force, every light "
                                "reaching every pixel), renders scenes with it, compares them with the CPU reference "
                                "ray-casting the same triangles, and writes a CSV (cost and error per variant and "
                                "scene, plus the tessellation's own error as the 'geometry' row), a cost-vs-error "
                                "chart and per-pixel error maps (log10 relative error, colour scale below). Shadow "
                                "rows (--shadow-rows) render --shadow-scene with the exact variant under each shadow "
                                "setting and compare it with the reference's shadow rays: relative RMSE of the frame, "
                                "and the share of pixels whose lit/shadowed state, each casting light alone, differs "
                                "outside a penumbra band of " + std::to_string(kShadowBandPx) + " pixels; their cost "
                                "is the shadow and lighting passes' ms. Transparency rows (--transparency-rows) "
                                "render --transparency-scene with the exact variant, no shadows, and each ordering "
                                "of BLEND surfaces against the reference's exact per-ray compositing; their cost is "
                                "the transparency pass's and the frame's ms.",
                                specs);
    return 0;
  }
  const AccuracyRequest r = readRequest(args);
  auto context = createHeadlessContext(r.platform);
  const ContextInfo& info = context->info();
  const TimingMode mode = chooseTimingMode(r.timing, info.renderer);
  std::printf("renderer: %s | timing: %s\n", info.renderer.c_str(), describe(mode));
  makeOutputFolder("--out-dir", r.dir);
  const ShaderLibrary shaders;
  const AccuracyCosts costs = measureCosts(shaders, r, mode);

  const std::string csvPath = (r.dir / "accuracy.csv").string();
  // Opened with the CSV, so that an unwritable folder fails at once; both are renamed into place at the end.
  OutputFile provenanceFile(provenancePath(csvPath));
  OutputFile csvFile(csvPath);
  std::printf("levels: 8-bit sRGB after exposure and the %s tone curve (--tonemap)\n", toString(r.curve));
  AccuracyTable table(csvFile.stream());
  compareVariants(shaders, r, costs, mode, table);
  compareShadowRows(shaders, r, costs, mode, table);
  compareTransparencyRows(shaders, r, costs, mode, table);
  csvFile.commit();
  provenanceFile.write([&](std::ostream& out) { writeKeyValues(out, csvProvenance(r, info, mode)); });
  std::printf("wrote %s (provenance in %s) and error maps error-VARIANT-SCENE.png in %s\n", csvPath.c_str(),
              provenancePath(csvPath).c_str(), r.dir.string().c_str());
  if (r.slices) writeSlices(shaders, r.variants, r.sliceGrid, r.dir);
  checkGlError("accuracy");
  if (!args.has("--no-chart") && costs.pairs.empty()) {
    std::fprintf(stderr, "pbr accuracy: chart skipped (its x axis is the cost per pair, not measured with --no-cost)\n");
  } else if (!args.has("--no-chart")) {
    const std::string png = (r.dir / "accuracy.png").string();
    // The CSV is the result; a machine without matplotlib still gets it.
    if (runChartScript("plot_accuracy.py", {csvPath, png})) std::printf("wrote %s\n", png.c_str());
    else std::fprintf(stderr, "pbr accuracy: chart skipped (scripts/plot_accuracy.py needs python3-matplotlib)\n");
  }
  return 0;
}

}  // namespace pbr
