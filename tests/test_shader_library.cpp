// Tests of pbr::ShaderLibrary on the driver: defines and files included repeatedly reach the compiler, driver
// errors map back to the original file:line, and every program the renderer builds from the project's shaders
// compiles.
#include <doctest/doctest.h>

#include <cstdint>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "core/scene/binding_table.hpp"
#include "core/gl/environment_maps.hpp"
#include "core/gl/gl_objects.hpp"
#include "core/gl/shader_library.hpp"
#include "gbuffer/gbuffer_bindings.hpp"
#include "gbuffer/gbuffer_pass.hpp"
#include "debug/debug_channel.hpp"
#include "debug/gbuffer_debug_pass.hpp"
#include "lighting/light_clusters.hpp"
#include "lighting/lighting_bindings.hpp"
#include "lighting/lighting_pass.hpp"
#include "core/scene/shading_model.hpp"
#include "post/fxaa_pass.hpp"
#include "post/post_pass.hpp"
#include "tests/gl_test_context.hpp"
#include "tests/shader_tree.hpp"

using namespace pbr;
using namespace pbr::test;

namespace {

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

// Runs a one-invocation compute program and returns the uint it stores at binding 0.
uint32_t dispatchScalar(const pbr::Program& program) {
  const uint32_t sentinel = 0xdeadbeefu;
  pbr::Buffer out("test.scalar", sizeof(uint32_t), &sentinel);
  out.bindBase(GL_SHADER_STORAGE_BUFFER, 0);
  program.use();
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  uint32_t value = 0;
  glGetNamedBufferSubData(out.id(), 0, sizeof(value), &value);
  return value;
}

}  // namespace

TEST_CASE("shader library: a file included repeatedly, also from both branches of an #if, is defined once") {
  PBR_REQUIRE_GL();
  const TempShaderTree tree;
  tree.write("util.glsl", "uint twice(uint x) { return 2u * x; }\n");
  tree.write("inc/uses_util.glsl", "#include \"../util.glsl\"\nuint quadruple(uint x) { return twice(twice(x)); }\n");
  // If the expander dropped the second textual copy, MODE 0 would lose twice(): its first copy sits in the
  // branch the preprocessor discards.
  tree.write("main.comp", std::string(kComputeHeader) +
                              "#if MODE\n"
                              "#include \"util.glsl\"\n"
                              "#else\n"
                              "#include \"util.glsl\"\n"
                              "#endif\n"
                              "#include \"util.glsl\"\n"
                              "#include \"inc/uses_util.glsl\"\n"
                              "layout(std430, binding = 0) buffer Out { uint value; };\n"
                              "void main() { value = quadruple(5u) + twice(1u); }\n");
  const ShaderLibrary lib(tree.root());
  for (const char* mode : {"0", "1"}) {
    CAPTURE(mode);
    const ShaderDefines defines = {{"MODE", mode}};
    CHECK(occurrences(lib.expand("main.comp", defines).text, "uint twice(") == 4);
    uint32_t value = 0;
    CHECK_NOTHROW(value = dispatchScalar(lib.compute("main.comp", defines)));
    CHECK(value == 22u);
  }
}

TEST_CASE("shader library: defines follow #version and reach the compiler") {
  const TempShaderTree tree;
  tree.write("t.comp", std::string(kComputeHeader) +
                           "layout(std430, binding = 0) buffer Out { uint value; };\n"
                           "void main() { value = VALUE; }\n");
  const ShaderLibrary lib(tree.root());

  const std::vector<std::string> text = lines(lib.expand("t.comp", {{"VALUE", "7u"}, {"OTHER", "1"}}).text);
  REQUIRE(text.size() >= 3);
  CHECK(text[0] == "#version 450 core");
  CHECK(text[1] == "#define VALUE 7u");
  CHECK(text[2] == "#define OTHER 1");

  PBR_REQUIRE_GL();
  for (const auto& [define, expected] : {std::pair<const char*, uint32_t>{"7u", 7u}, {"123456u", 123456u}}) {
    CAPTURE(define);
    CHECK(dispatchScalar(lib.compute("t.comp", {{"VALUE", define}})) == expected);
  }
}

TEST_CASE("shader library: driver errors in included and root files map to the original file:line") {
  PBR_REQUIRE_GL();
  const TempShaderTree tree;
  tree.write("inc/helper.glsl", "// helper\n// helper\nfloat helperValue() { return 1.0; }\n");
  // The error sits on line 4, after a nested include that must not shift this file's numbering. It is a
  // return-type error because Mesa reports those with the right source string (see the next test case).
  tree.write("inc/broken.glsl",
             "// deliberately broken\n"
             "#include \"helper.glsl\"\n"
             "float fine() { return helperValue(); }\n"
             "float broken() { return vec2(1.0); }\n");
  tree.write("include_error.comp", std::string(kComputeHeader) + "#include \"inc/broken.glsl\"\nvoid main() {}\n");
  tree.write("root_error.comp", std::string(kComputeHeader) +
                                    "#include \"inc/helper.glsl\"\n"
                                    "void main() {\n"
                                    "  float x = undefined_in_root;\n"
                                    "}\n");
  const ShaderLibrary lib(tree.root());

  const std::string inInclude = errorOf([&] { lib.compute("include_error.comp", {{"UNUSED", "1"}}); });
  CHECK(contains(inInclude, tree.display("inc/broken.glsl") + ":4:"));

  // Defines add lines to the compiled text; the reported line must still be the file's own.
  const std::string inRoot = errorOf([&] { lib.compute("root_error.comp", {{"A", "1"}, {"B", "2"}}); });
  CHECK(contains(inRoot, tree.display("root_error.comp") + ":5:"));
  CHECK(contains(inRoot, "undefined_in_root"));
}

// Mesa (22.3 at least) reports undeclared identifiers and most expression errors with source string 0 whatever
// the last #line said, so mapping by source number alone names the root file with the included file's line.
TEST_CASE("shader library: an undeclared identifier in an included file is reported in that file") {
  PBR_REQUIRE_GL();
  const TempShaderTree tree;
  tree.write("inc/undeclared.glsl", "// line 1\n// line 2\nvoid f() { float x = undefined_in_include; }\n");
  tree.write("main.comp", std::string(kComputeHeader) + "#include \"inc/undeclared.glsl\"\nvoid main() {}\n");
  const ShaderLibrary lib(tree.root());

  const std::string message = errorOf([&] { lib.compute("main.comp"); });
  CAPTURE(message);
  CHECK(contains(message, tree.display("inc/undeclared.glsl") + ":3:"));
  CHECK_FALSE(contains(message, tree.display("main.comp") + ":3:"));
}

namespace {

using DefineSets = std::vector<ShaderDefines>;

// Every combination of 0/1 for the given flags.
DefineSets flagCombinations(const std::vector<std::string>& flags) {
  DefineSets sets;
  for (unsigned bits = 0; bits < (1u << flags.size()); ++bits) {
    ShaderDefines defines;
    for (size_t i = 0; i < flags.size(); ++i) defines.push_back({flags[i], (bits >> i) & 1u ? "1" : "0"});
    sets.push_back(defines);
  }
  return sets;
}

// Each permutation with the binding defines of the module that compiles it, as its pass does.
void checkComputeCompiles(const std::string& file, const DefineSets& permutations,
                          const ShaderDefines& bindings = pbr::lightingBindingDefines()) {
  const ShaderLibrary shaders;
  for (const ShaderDefines& defines : permutations) {
    CAPTURE(file);
    const std::string described = describeDefines(defines);
    CAPTURE(described);
    CHECK_NOTHROW(shaders.compute(file, pbr::concat(defines, bindings)));
  }
}

}  // namespace

TEST_CASE("shader library: every program the renderer builds from the project's shaders compiles") {
  PBR_REQUIRE_GL();
  // Every model x culling x stats x (light chunking, spot lights) with the standard PBR terms, then every form of
  // every PBR term once.
  DefineSets lighting, ibl;
  const pbr::Texture pairCounts("test.pairCounts", GL_RG32UI, 1, 1);
  for (const pbr::ShadingModel model : {pbr::ShadingModel::Pbr, pbr::ShadingModel::BlinnPhong}) {
    for (const bool clustered : {false, true}) {
      for (const bool stats : {false, true}) {
        pbr::LightingOptions options;
        options.model = model;
        options.stats = stats;
        // The per-pixel pair counts of the efficiency view, alone and with the per-workgroup ones.
        options.pairCounts = &pairCounts;
        lighting.push_back(pbr::lightingPermutation(options, clustered, pbr::HdrFormat::Rgba16f));
        lighting.push_back(pbr::lightingPermutation(options, clustered, pbr::HdrFormat::Rgba16f, true));
        options.pairCounts = nullptr;
        lighting.push_back(pbr::lightingPermutation(options, clustered, pbr::HdrFormat::Rgba16f));
        lighting.push_back(pbr::lightingPermutation(options, clustered, pbr::HdrFormat::Rgba16f, true));
        lighting.push_back(pbr::lightingPermutation(options, clustered, pbr::HdrFormat::Rgba16f, false, {true, false}));
        lighting.push_back(pbr::lightingPermutation(options, clustered, pbr::HdrFormat::Rgba16f, false, {false, true}));
        lighting.push_back(pbr::lightingPermutation(options, clustered, pbr::HdrFormat::Rgba16f, true, {true, true}));
        // With unlit surfaces in the G-buffer, in one dispatch and in light chunks.
        options.unlitSurfaces = true;
        lighting.push_back(pbr::lightingPermutation(options, clustered, pbr::HdrFormat::Rgba16f));
        lighting.push_back(pbr::lightingPermutation(options, clustered, pbr::HdrFormat::Rgba16f, true));
        options.unlitSurfaces = false;
        // The IBL permutations exist for PBR only (LightingPass never asks for them with Blinn-Phong).
        const pbr::EnvironmentMaps maps;
        options.environment = &maps;
        if (model == pbr::ShadingModel::Pbr) {
          ibl.push_back(pbr::lightingPermutation(options, clustered, pbr::HdrFormat::Rgba16f));
          ibl.push_back(pbr::lightingPermutation(options, clustered, pbr::HdrFormat::Rgba16f, true));
        }
      }
    }
  }
  for (const char* variant : {"visibility=hammon", "visibility=separable", "ndf=beckmann", "fresnel=exact",
                              "fresnel=schlick-sg", "diffuse=lambert", "diffuse=burley", "diffuse=lambert-1-f-vh"}) {
    pbr::LightingOptions options;
    options.variant = pbr::parseShadingVariant(variant);
    lighting.push_back(pbr::lightingPermutation(options, true, pbr::HdrFormat::Rgba16f));
  }
  checkComputeCompiles("lighting/deferred.comp", lighting);
  checkComputeCompiles("lighting/deferred.comp", ibl);
  checkComputeCompiles("lighting/cluster_scan.comp", flagCombinations({"ASSIGN_STATS"}));
  DefineSets lightPass;
  const std::vector<std::string> lightPassFlags = {"SPOT_LIGHTS", "LIGHT_COUNT", "LIGHT_MARK", "ASSIGN_STATS"};
  using Build = pbr::LightClusters::LightPassBuild;
  for (const ShaderDefines& flags : flagCombinations(lightPassFlags)) {
    const auto on = [&](size_t i) { return flags[i].value == "1"; };
    for (const Build build : {Build::Inline, Build::Queued, Build::EveryLight, Build::PerCluster}) {
      lightPass.push_back(pbr::LightClusters::lightPassPermutation(on(0), on(1), on(2), on(3), build));
    }
  }
  checkComputeCompiles("lighting/cluster_lights.comp", lightPass);
  checkComputeCompiles("lighting/cluster_occupancy.comp", DefineSets{ShaderDefines{}});
  checkComputeCompiles("lighting/cluster_activate.comp", DefineSets{ShaderDefines{}});
  checkComputeCompiles("lighting/cluster_fill.comp", flagCombinations({"WORKGROUP_PER_SLOT"}));
  checkComputeCompiles("lighting/cluster_debug.comp", flagCombinations({"DEBUG_SLICES"}));
  checkComputeCompiles("lighting/efficiency_debug.comp", DefineSets{ShaderDefines{}});
  for (const pbr::DebugChannel channel : pbr::kDebugChannels) {
    if (!pbr::isGBufferChannel(channel)) continue;
    checkComputeCompiles("lighting/gbuffer_debug.comp", DefineSets{pbr::GBufferDebugPass::permutation(channel)});
  }
  DefineSets curves;
  for (const pbr::ToneCurve curve : pbr::kToneCurves) {
    for (const bool autoExposure : {false, true}) curves.push_back(pbr::PostPass::permutation(curve, autoExposure));
  }
  checkComputeCompiles("post/post.comp", curves, pbr::bindingDefines({pbr::kPostUbo, pbr::kExposureSsbo}));
  checkComputeCompiles("post/exposure_histogram.comp", DefineSets{pbr::ExposureMeter::defines()});
  checkComputeCompiles("post/exposure_adapt.comp", DefineSets{pbr::ExposureMeter::defines()});
  checkComputeCompiles("post/fxaa.comp", DefineSets{pbr::FxaaPass::defines(false), pbr::FxaaPass::defines(true)});
  const ShaderLibrary shaders;
  const std::vector<std::string> gbufferFlags = {"BASE_COLOR_MAP", "METALLIC_ROUGHNESS_MAP", "NORMAL_MAP",
                                                 "OCCLUSION_MAP", "EMISSIVE_MAP", "ALPHA_MASK", "UNLIT"};
  // The list above must be every define the G-buffer pass chooses.
  std::vector<std::string> chosen;
  for (const pbr::ShaderDefine& d : pbr::GBufferPass::permutation(pbr::Material{})) chosen.push_back(d.name);
  CHECK(chosen == gbufferFlags);
  for (const ShaderDefines& defines : flagCombinations(gbufferFlags)) {
    const std::string described = describeDefines(defines);
    CAPTURE(described);
    CHECK_NOTHROW(
        shaders.graphics("gbuffer/gbuffer.vert", "gbuffer/gbuffer.frag", pbr::concat(defines, pbr::gbufferBindingDefines())));
  }
  // The optional vertex streams (GBufferPass::streamPermutation) with no map and with every map.
  const std::vector<std::string> streamFlags = {"VERTEX_COLORS", "UV1"};
  std::vector<std::string> streamsChosen;
  for (const pbr::ShaderDefine& d : pbr::GBufferPass::streamPermutation(pbr::MeshData{})) streamsChosen.push_back(d.name);
  CHECK(streamsChosen == streamFlags);
  for (const ShaderDefines& streams : flagCombinations(streamFlags)) {
    for (const char* maps : {"0", "1"}) {
      ShaderDefines defines = streams;
      for (const std::string& flag : gbufferFlags) defines.push_back({flag, maps});
      const std::string described = describeDefines(defines);
      CAPTURE(described);
      CHECK_NOTHROW(shaders.graphics("gbuffer/gbuffer.vert", "gbuffer/gbuffer.frag",
                                     pbr::concat(defines, pbr::gbufferBindingDefines())));
    }
  }
  // The shadow casters' depth permutations (GBufferPass::renderDepth).
  for (const ShaderDefines& defines :
       flagCombinations({"ALPHA_MASK", "BASE_COLOR_MAP", "VERTEX_COLORS", "UV1", "VIEWPORT_FROM_VERTEX"})) {
    const std::string described = describeDefines(defines);
    CAPTURE(described);
    CHECK_NOTHROW(shaders.graphics("gbuffer/shadow_depth.vert", "gbuffer/shadow_depth.frag",
                                   pbr::concat(defines, pbr::gbufferBindingDefines())));
  }
}
