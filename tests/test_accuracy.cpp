#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "app/accuracy/accuracy_variants.hpp"
#include "app/accuracy/brdf_slice.hpp"
#include "tests/cli_util.hpp"
#include "tests/gl_test_context.hpp"

using namespace pbr;

namespace {

double meanOver(const BrdfSlice& s, double loDeg, double hiDeg) {
  double sum = 0.0;
  int n = 0;
  for (int r = 0; r < s.roughnesses; ++r)
    for (int a = 0; a < s.angles; ++a) {
      const double deg = (a + 0.5) * 90.0 / s.angles;
      if (deg >= loDeg && deg <= hiDeg) sum += s.at(a, r), ++n;
    }
  return sum / n;
}

// The fields of a CSV line whose quoted fields hold no quotes.
std::vector<std::string> csvFields(const std::string& line) {
  std::vector<std::string> out(1);
  bool quoted = false;
  for (const char c : line) {
    if (c == '"') quoted = !quoted;
    else if (c == ',' && !quoted) out.emplace_back();
    else out.back() += c;
  }
  return out;
}

// The rows of accuracy.csv by variant name, each as column name -> value.
std::map<std::string, std::map<std::string, std::string>> csvRows(const std::string& text) {
  std::istringstream in(text);
  std::string line;
  std::getline(in, line);  // the header row comes first
  const std::vector<std::string> header = csvFields(line);
  std::map<std::string, std::map<std::string, std::string>> rows;
  while (std::getline(in, line)) {
    const std::vector<std::string> f = csvFields(line);
    REQUIRE(f.size() == header.size());
    for (size_t i = 0; i < f.size(); ++i) rows[f[0]][header[i]] = f[i];
  }
  return rows;
}

}  // namespace

// A metal has no diffuse lobe and the same Schlick Fresnel in the GLSL and reference models, so with exact
// Fresnel selected the slice isolates the visibility term.
TEST_CASE("accuracy slices: the exact variant matches the reference BRDF and Hammon's form errs most at grazing angles") {
  PBR_REQUIRE_GL();
  const ShaderLibrary shaders;
  const SliceMaterial metal{glm::vec3(0.95f, 0.64f, 0.54f), 1.0f};
  const BrdfSlice exact = computeBrdfSlice(shaders, parseShadingVariant("fresnel=exact"), metal, 45, 16);
  float worstExact = 0.0f;
  for (float e : exact.relativeError) worstExact = std::max(worstExact, e);
  MESSAGE("exact variant: largest relative BRDF error " << worstExact);
  CHECK(worstExact < 1e-3f);

  const BrdfSlice hammon = computeBrdfSlice(shaders, parseShadingVariant("visibility=hammon,fresnel=exact"), metal, 45, 16);
  for (int r = 0; r < hammon.roughnesses; ++r) {
    int worst = 0;
    for (int a = 1; a < hammon.angles; ++a)
      if (hammon.at(a, r) > hammon.at(worst, r)) worst = a;
    if (hammon.at(worst, r) < 1e-3f) continue;  // roughness near 1, where both forms agree
    CAPTURE(r);
    CHECK((worst + 0.5) * 90.0 / hammon.angles > 60.0);
  }
  const double grazing = meanOver(hammon, 70.0, 90.0), frontal = meanOver(hammon, 0.0, 30.0);
  MESSAGE("Hammon: mean relative error " << frontal << " at 0-30 degrees, " << grazing << " at 70-90 degrees");
  CHECK(grazing > 5.0 * frontal);
}

TEST_CASE("pbr accuracy: one CSV row per variant with cost per pair and error, a geometry row, error maps, slices") {
  PBR_REQUIRE_GL();
  const test::TempDir dir;
  const test::PbrRun run = test::runPbr(dir, {"accuracy", "--size", "32x18", "--pair-size", "32x18", "--pair-lights",
                                              "4", "--rounds", "3", "--scenes", "fresnel-floor:40", "--out-dir",
                                              dir.file("acc"), "--no-chart", "--brdf-slices", "--brdf-slice-size",
                                              "16x8",
                                              "--shadow-rows", "none", "--transparency-rows", "none"});
  REQUIRE_MESSAGE(run.exitCode == 0, run.err);
  std::istringstream csv(test::readFile(dir.path() / "acc" / "accuracy.csv"));
  std::string line;
  std::getline(csv, line);
  CHECK(line == "variant,scene,model,terms,hdr_format,gbuffer,ns_per_pair_median,ns_per_pair_p10,ns_per_pair_p90,"
                "fixed_share,relative_rmse,mean_levels,max_levels,share_over_2,pixels,shadow_filter,shadow_atlas,"
                "shadow_ms_median,lighting_ms_median,passes_ms_median,passes_ms_p10,passes_ms_p90,misclassified_share,"
                "shadow_pixels,transparency,transparency_ms_median,transparency_ms_p10,transparency_ms_p90,"
                "frame_ms_median,frame_ms_p10,frame_ms_p90");
  std::getline(csv, line);
  // A flat floor is tessellated exactly: its geometry error is zero.
  CHECK(line.rfind("geometry,fresnel-floor-40,reference,", 0) == 0);
  CHECK(line.find(",n/a,n/a,n/a,n/a,0,") != std::string::npos);
  const std::string provenance = test::readFile(dir.path() / "acc" / "accuracy.provenance.txt");
  CHECK(provenance.find("transparency_") == std::string::npos);
  CHECK(provenance.rfind("gl_renderer: ", 0) == 0);
  CHECK(provenance.find("\ntone_curve: aces-hill\n") != std::string::npos);
  size_t rows = 0;
  for (; std::getline(csv, line); ++rows) {
    CAPTURE(line);
    // The terms column is quoted and holds commas: the numbers follow it.
    std::vector<std::string> f;
    std::stringstream in(line.substr(line.rfind('"') + 2));
    for (std::string item; std::getline(in, item, ',');) f.push_back(item);
    // hdr_format, gbuffer, ns median, p10, p90, fixed share, rmse, mean, max, share, pixels, then the shadow rows'
    // nine columns and the transparency rows' seven, not applicable here
    REQUIRE(f.size() == 27);
    CHECK(line.substr(line.rfind('"') + 2).find(",-,-,n/a,n/a,n/a,n/a,n/a,n/a,n/a,-,n/a,n/a,n/a,n/a,n/a,n/a") !=
          std::string::npos);
    const std::string variant = line.substr(0, line.find(','));
    CHECK(variant == accuracyLadder()[rows].name);
    const double p10 = std::stod(f[3]), median = std::stod(f[2]), p90 = std::stod(f[4]);
    CHECK(p10 > 0.0);
    CHECK(p10 <= median);
    CHECK(median <= p90);
    const double rmse = std::stod(f[6]);
    CHECK(std::isfinite(rmse));
    CHECK(rmse >= 0.0);
    CHECK(std::stoi(f[10]) > 0);
    CHECK(std::filesystem::exists(dir.path() / "acc" / ("error-" + variant + "-fresnel-floor-40.png")));
  }
  CHECK(rows == accuracyLadder().size());
  CHECK(std::filesystem::exists(dir.path() / "acc" / "slice-hammon-metal.png"));
  CHECK(test::readFile(dir.path() / "acc" / "slices.csv").find("hammon,dielectric,") != std::string::npos);
}

TEST_CASE("pbr render --variant and --hdr-format select a permutation, unknown values are usage errors") {
  PBR_REQUIRE_GL();
  const test::TempDir dir;
  const test::PbrRun ok = test::runPbr(dir, {"render", "--size", "32x18", "--scene", "sphere-grid", "--variant",
                                             "visibility=separable,ndf=beckmann,fresnel=exact,diffuse=burley",
                                             "--hdr-format", "r11g11b10f", "--hdr", dir.file("f.pfm")});
  REQUIRE_MESSAGE(ok.exitCode == 0, ok.err);
  CHECK(ok.out.find("visibility=separable,ndf=beckmann,fresnel=exact,diffuse=burley") != std::string::npos);
  for (const std::vector<std::string>& bad : {std::vector<std::string>{"--variant", "ndf=phong"},
                                              std::vector<std::string>{"--variant", "specular=ggx"},
                                              std::vector<std::string>{"--variant", "ndf"},
                                              std::vector<std::string>{"--hdr-format", "rgba8"}}) {
    std::vector<std::string> args = {"render", "--size", "32x18"};
    args.insert(args.end(), bad.begin(), bad.end());
    const test::PbrRun run = test::runPbr(dir, args);
    CAPTURE(bad[1]);
    CHECK(run.exitCode == 2);
    CHECK(test::isOneLine(run.err));
  }
}

TEST_CASE("pbr render and pbr reference --variant study: the study's model, every key printed, alone only") {
  PBR_REQUIRE_GL();
  const test::TempDir dir;
  const std::string study = "visibility=hammon,ndf=ggx,fresnel=schlick,diffuse=lambert-1-f-vh";
  const test::PbrRun render = test::runPbr(dir, {"render", "--size", "32x18", "--scene", "fresnel-floor", "--variant",
                                                 "study", "--hdr", dir.file("gpu.pfm")});
  REQUIRE_MESSAGE(render.exitCode == 0, render.err);
  CHECK(render.out.find(study) != std::string::npos);
  const test::PbrRun reference = test::runPbr(dir, {"reference", "--size", "32x18", "--scene", "fresnel-floor",
                                                    "--variant", "study", "--threads", "1", "--hdr", dir.file("ref.pfm")});
  REQUIRE_MESSAGE(reference.exitCode == 0, reference.err);
  CHECK(reference.out.find(study) != std::string::npos);
  // The reference's own model is the default its help states.
  const test::PbrRun help = test::runPbr(dir, {"reference", "--help"});
  CHECK(help.out.find("visibility=exact,ndf=ggx,fresnel=exact,diffuse=lambert-1-f") != std::string::npos);
  CHECK(test::runPbr(dir, {"render", "--help"}).out.find("study") != std::string::npos);
  for (const std::vector<std::string>& bad : {std::vector<std::string>{"render", "--variant", "study,fresnel=exact"},
                                              std::vector<std::string>{"reference", "--variant", "study,ndf=ggx"},
                                              std::vector<std::string>{"reference", "--variant", "diffuse=burley"}}) {
    std::vector<std::string> args = bad;
    args.insert(args.end(), {"--size", "16x9", "--hdr", dir.file("bad.pfm")});
    const test::PbrRun run = test::runPbr(dir, args);
    CAPTURE(bad[2]);
    CHECK(run.exitCode == 2);
    CHECK(test::isOneLine(run.err));
  }
}

// The shadow rows on the built-in shadow-trio scene (a sun, a spot and a point light over a sphere and a box on a
// floor) at 160x90: each light's lit/shadowed state against the reference's shadow rays, outside a 2-pixel band.
TEST_CASE("pbr accuracy shadow rows: pcf3x3 at a 4096 atlas agrees with the reference's shadow rays, at 256 less") {
  PBR_REQUIRE_GL();
  const test::TempDir dir;
  const test::PbrRun run = test::runPbr(
      dir, {"accuracy", "--variants", "exact", "--scenes", "fresnel-floor:0", "--size", "160x90", "--pair-size",
            "32x18", "--pair-lights", "4", "--rounds", "2", "--shadow-rows", "unshadowed,pcf3x3,pcf3x3:256",
            "--shadow-cost-size", "160x90", "--transparency-rows", "none", "--out-dir", dir.file("acc"),
            "--no-chart"});
  REQUIRE_MESSAGE(run.exitCode == 0, run.err);
  const std::string text = test::readFile(dir.path() / "acc" / "accuracy.csv");
  CHECK(test::readFile(dir.path() / "acc" / "accuracy.provenance.txt").find("\nshadow_state: ") != std::string::npos);
  auto rows = csvRows(text);
  REQUIRE(rows.count("unshadowed") == 1);
  REQUIRE(rows.count("shadow-pcf3x3-4096") == 1);
  REQUIRE(rows.count("shadow-pcf3x3-256") == 1);
  auto number = [&](const std::string& row, const std::string& column) { return std::stod(rows[row][column]); };
  for (const char* row : {"unshadowed", "shadow-pcf3x3-4096", "shadow-pcf3x3-256"}) {
    CAPTURE(row);
    CHECK(rows[row]["scene"] == "shadow-trio");
    CHECK(rows[row]["ns_per_pair_median"] == "n/a");
    CHECK(number(row, "pixels") > 5000);
    // Every row compares the same pixels: which are compared depends on the reference and the unshadowed frames.
    CHECK(rows[row]["shadow_pixels"] == rows["unshadowed"]["shadow_pixels"]);
    CHECK(number(row, "lighting_ms_median") > 0.0);
    CHECK(number(row, "passes_ms_p10") <= number(row, "passes_ms_median"));
    CHECK(number(row, "passes_ms_median") <= number(row, "passes_ms_p90"));
    CHECK(std::filesystem::exists(dir.path() / "acc" / ("error-" + std::string(row) + "-shadow-trio.png")));
  }
  CHECK(rows["unshadowed"]["shadow_filter"] == "none");
  CHECK(rows["shadow-pcf3x3-256"]["shadow_atlas"] == "256");
  CHECK(number("unshadowed", "shadow_ms_median") == 0.0);  // no light casts: no shadow pass
  CHECK(number("shadow-pcf3x3-4096", "shadow_ms_median") > 0.0);
  const double none = number("unshadowed", "misclassified_share");
  const double fine = number("shadow-pcf3x3-4096", "misclassified_share");
  const double coarse = number("shadow-pcf3x3-256", "misclassified_share");
  MESSAGE("misclassified: unshadowed " << none << ", pcf3x3 at 4096 " << fine << ", at 256 " << coarse << " of "
                                       << rows["unshadowed"]["shadow_pixels"] << " light-pixels");
  // Unshadowed, every pixel the reference shadows is wrong: the scene must have shadows to miss.
  CHECK(none > 0.03);
  CHECK(fine < 0.005);
  CHECK(coarse > fine);
  CHECK(coarse < none);
  CHECK(number("shadow-pcf3x3-4096", "relative_rmse") < number("shadow-pcf3x3-256", "relative_rmse"));
  CHECK(number("shadow-pcf3x3-256", "relative_rmse") < number("unshadowed", "relative_rmse"));
}

// The transparency rows on the built-in transparency scene (two panes of alpha 0.5 and 0.3 crossing along a vertical
// line, a 0.6 pane in front of them, a double-sided 0.7 pane seen from its back, over two spheres on a floor) at
// 160x90, the exact variant without shadows against the reference's exact per-ray compositing. Sorting by the panes'
// centres composites one side of the crossing in the wrong order; oit averages the layers of every overlap instead.
// On this scene that spreads less error than sorting's wrong side (measured: relative RMSE 0.017 against 0.029);
// the exact lists order every fragment, leaving the lean G-buffer's error (0.0074 on the scene without panes).
TEST_CASE("pbr accuracy transparency rows: every ordering against the reference, exact the closest, oit then") {
  PBR_REQUIRE_GL();
  const test::TempDir dir;
  const test::PbrRun run = test::runPbr(
      dir, {"accuracy", "--variants", "exact", "--scenes", "fresnel-floor:0", "--size", "160x90", "--pair-size",
            "32x18", "--pair-lights", "4", "--rounds", "2", "--shadow-rows", "none", "--transparency-cost-size",
            "160x90", "--out-dir", dir.file("acc"), "--no-chart"});
  REQUIRE_MESSAGE(run.exitCode == 0, run.err);
  const std::string text = test::readFile(dir.path() / "acc" / "accuracy.csv");
  CHECK(test::readFile(dir.path() / "acc" / "accuracy.provenance.txt")
            .find("\ntransparency_cost_frame: transparency, 160x90, ") != std::string::npos);
  auto rows = csvRows(text);
  auto number = [&](const std::string& row, const std::string& column) { return std::stod(rows[row][column]); };
  // The other row kinds leave the transparency columns empty.
  CHECK(rows["exact"]["transparency"] == "-");
  CHECK(rows["exact"]["frame_ms_median"] == "n/a");
  for (const char* ordering : {"sorted", "oit", "exact"}) {
    const std::string row = std::string("transparency-") + ordering;
    CAPTURE(row);
    REQUIRE(rows.count(row) == 1);
    CHECK(rows[row]["scene"] == "transparency");
    CHECK(rows[row]["transparency"] == ordering);
    CHECK(rows[row]["terms"] == "visibility=exact,ndf=ggx,fresnel=exact,diffuse=lambert-1-f");
    CHECK(rows[row]["ns_per_pair_median"] == "n/a");
    CHECK(rows[row]["shadow_filter"] == "-");
    CHECK(rows[row]["passes_ms_median"] == "n/a");
    CHECK(number(row, "pixels") > 5000);
    CHECK(rows[row]["pixels"] == rows["transparency-sorted"]["pixels"]);
    const double rmse = number(row, "relative_rmse");
    CHECK(std::isfinite(rmse));
    CHECK(rmse > 0.0);
    CHECK(number(row, "transparency_ms_p10") > 0.0);
    CHECK(number(row, "transparency_ms_p10") <= number(row, "transparency_ms_median"));
    CHECK(number(row, "transparency_ms_median") <= number(row, "transparency_ms_p90"));
    CHECK(number(row, "frame_ms_p10") <= number(row, "frame_ms_median"));
    CHECK(number(row, "frame_ms_median") <= number(row, "frame_ms_p90"));
    // The frame holds the transparency pass and the passes before and after it.
    CHECK(number(row, "frame_ms_median") > number(row, "transparency_ms_median"));
    CHECK(std::filesystem::exists(dir.path() / "acc" / ("error-" + row + "-transparency.png")));
  }
  const double sorted = number("transparency-sorted", "relative_rmse");
  const double oit = number("transparency-oit", "relative_rmse");
  const double exact = number("transparency-exact", "relative_rmse");
  MESSAGE("relative RMSE against the reference: sorted " << sorted << ", oit " << oit << ", exact " << exact);
  CHECK(oit < sorted);
  CHECK(exact < 0.6 * oit);
}

// Refused before any context is made or frame rendered; were a refusal missing, the other options keep the run short.
TEST_CASE("pbr accuracy transparency rows: an unknown ordering or a scene without BLEND is a usage error") {
  const test::TempDir dir;
  for (const std::vector<std::string>& bad : {std::vector<std::string>{"--transparency-rows", "sorted,depth-peeling"},
                                              std::vector<std::string>{"--transparency-rows", ","},
                                              std::vector<std::string>{"--transparency-scene", "fresnel-floor"}}) {
    std::vector<std::string> args = {"accuracy", "--variants", "exact", "--scenes", "fresnel-floor:0", "--size", "16x9",
                                     "--no-cost", "--shadow-rows", "none", "--out-dir", dir.file("acc")};
    args.insert(args.end(), bad.begin(), bad.end());
    const test::PbrRun run = test::runPbr(dir, args);
    CAPTURE(bad[1]);
    CHECK(run.exitCode == 2);
    CHECK(test::isOneLine(run.err));
  }
  CHECK_FALSE(std::filesystem::exists(dir.path() / "acc" / "accuracy.csv"));
}
