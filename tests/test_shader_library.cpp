// Tests of pbr::ShaderLibrary: #include resolution, define injection and the #line bookkeeping that maps driver
// errors back to the original files, on a scratch shader tree; then every program the renderer builds from the
// project's own shaders, and the binding numbers shared between GLSL and C++.
#include <doctest/doctest.h>

#include <unistd.h>

#include <cctype>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "core/binding_table.hpp"
#include "core/environment_maps.hpp"
#include "core/frame_block.hpp"
#include "core/shader_library.hpp"
#include "gbuffer/gbuffer_bindings.hpp"
#include "gbuffer/gbuffer_pass.hpp"
#include "lighting/brdf_grid.hpp"
#include "lighting/lighting_bindings.hpp"
#include "lighting/lighting_pass.hpp"
#include "lighting/shading_model.hpp"
#include "post/post_pass.hpp"
#include "tests/gl_test_context.hpp"

namespace fs = std::filesystem;
using pbr::ShaderDefines;
using pbr::ShaderError;
using pbr::ShaderLibrary;

namespace {

// A scratch shader root, unique per process and per tree so that parallel ctest processes never share one.
class TempShaderTree {
 public:
  TempShaderTree() {
    static int counter = 0;
    root_ = fs::temp_directory_path() /
            ("pbr_shader_library_test_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
    fs::remove_all(root_);
    fs::create_directories(root_);
  }
  ~TempShaderTree() {
    std::error_code ignored;
    fs::remove_all(root_, ignored);
  }
  TempShaderTree(const TempShaderTree&) = delete;
  TempShaderTree& operator=(const TempShaderTree&) = delete;

  const fs::path& root() const { return root_; }
  // How the library names a file of this tree in its messages: the root folder's name, then the relative path.
  std::string display(const std::string& relative) const { return root_.filename().string() + "/" + relative; }

  void write(const std::string& relative, const std::string& text) const {
    const fs::path path = root_ / relative;
    fs::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << text;
  }

 private:
  fs::path root_;
};

std::string errorOf(const std::function<void()>& action) {
  try {
    action();
  } catch (const ShaderError& e) {
    return e.what();
  }
  FAIL("expected a pbr::ShaderError");
  return {};
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

bool contains(const std::string& haystack, const std::string& needle) {
  return haystack.find(needle) != std::string::npos;
}

size_t occurrences(const std::string& haystack, const std::string& needle) {
  size_t count = 0;
  for (size_t at = haystack.find(needle); at != std::string::npos; at = haystack.find(needle, at + 1)) ++count;
  return count;
}

// Runs a one-invocation compute program and returns the uint it stores at binding 0.
uint32_t dispatchScalar(const pbr::Program& program) {
  const uint32_t sentinel = 0xdeadbeefu;
  pbr::Buffer out(sizeof(uint32_t), &sentinel);
  out.bindBase(GL_SHADER_STORAGE_BUFFER, 0);
  program.use();
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  uint32_t value = 0;
  glGetNamedBufferSubData(out.id(), 0, sizeof(value), &value);
  return value;
}

constexpr const char* kComputeHeader = "#version 450 core\nlayout(local_size_x = 1) in;\n";

}  // namespace

TEST_CASE("shader library: includes resolve next to the including file first, then from the root") {
  const TempShaderTree tree;
  tree.write("main.comp", std::string(kComputeHeader) +
                              "#include \"inc/a.glsl\"\n"
                              "// marker main\n");
  // "b.glsl" exists both next to inc/a.glsl and at the root: the including file's folder wins.
  tree.write("inc/a.glsl", "#include \"b.glsl\"\n#include \"top.glsl\"\n// marker inc/a\n");
  tree.write("inc/b.glsl", "#include \"deep/c.glsl\"\n// marker inc/b\n");
  tree.write("inc/deep/c.glsl", "// marker inc/deep/c\n");
  tree.write("b.glsl", "// marker root b\n");
  tree.write("top.glsl", "// marker top\n");

  const ShaderLibrary lib(tree.root());
  const pbr::ExpandedShader expanded = lib.expand("main.comp");
  for (const char* marker : {"// marker main", "// marker inc/a", "// marker inc/b", "// marker inc/deep/c",
                             "// marker top"}) {
    CAPTURE(marker);
    CHECK(occurrences(expanded.text, marker) == 1);
  }
  CHECK_FALSE(contains(expanded.text, "// marker root b"));
  // Depth-first order: c is spliced in before the rest of b, b before the rest of a.
  CHECK(expanded.text.find("// marker inc/deep/c") < expanded.text.find("// marker inc/b"));
  CHECK(expanded.text.find("// marker inc/b") < expanded.text.find("// marker top"));
  CHECK(expanded.text.find("// marker top") < expanded.text.find("// marker inc/a"));
  CHECK(expanded.text.find("// marker inc/a") < expanded.text.find("// marker main"));
  CHECK(expanded.files == std::vector<std::string>{tree.display("main.comp"), tree.display("inc/a.glsl"),
                                                   tree.display("inc/b.glsl"), tree.display("inc/deep/c.glsl"),
                                                   tree.display("top.glsl")});
}

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

TEST_CASE("shader library: include cycles, missing includes and a missing #version are errors naming file:line") {
  const TempShaderTree tree;
  tree.write("cycle.comp", std::string(kComputeHeader) + "#include \"a.glsl\"\n");
  tree.write("a.glsl", "// a\n#include \"b.glsl\"\n");
  tree.write("b.glsl", "// b\n// b\n#include \"a.glsl\"\n");
  tree.write("missing.comp", std::string(kComputeHeader) + "#include \"inc/has_missing.glsl\"\n");
  tree.write("inc/has_missing.glsl", "// first\n#include \"nowhere/gone.glsl\"\n");
  tree.write("noversion.comp", "// a comment before the version\n#version 450 core\nvoid main() {}\n");
  const ShaderLibrary lib(tree.root());

  const std::string cycle = errorOf([&] { lib.expand("cycle.comp"); });
  CHECK(contains(cycle, tree.display("b.glsl") + ":3:"));
  CHECK(contains(cycle, "a.glsl"));

  const std::string missing = errorOf([&] { lib.expand("missing.comp"); });
  CHECK(contains(missing, tree.display("inc/has_missing.glsl") + ":2:"));
  CHECK(contains(missing, "nowhere/gone.glsl"));

  const std::string noVersion = errorOf([&] { lib.expand("noversion.comp"); });
  CHECK(contains(noVersion, tree.display("noversion.comp") + ":1:"));
  CHECK(contains(noVersion, "#version"));
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

TEST_CASE("shader library: remapShaderLog rewrites Mesa and NVIDIA log lines to file:line") {
  const std::vector<std::string> files = {"fileA", "fileB"};
  CHECK(pbr::remapShaderLog("0:12(5): error: foo", files) == "fileA:12: error: foo");
  CHECK(pbr::remapShaderLog("1(7) : error C0000: bar", files) == "fileB:7: error C0000: bar");
  CHECK(pbr::remapShaderLog("warning: something unrelated", files) == "warning: something unrelated");
  CHECK(pbr::remapShaderLog("0:12(5): error: foo\n1(7) : error C0000: bar\nlink note\n", files) ==
        "fileA:12: error: foo\nfileB:7: error C0000: bar\nlink note");

  std::string outOfRange;
  CHECK_NOTHROW(outOfRange = pbr::remapShaderLog("5:3(1): error: baz", files));
  CHECK(contains(outOfRange, "5"));
  CHECK(contains(outOfRange, ":3: error: baz"));
  CHECK_FALSE(contains(outOfRange, "fileA"));
  CHECK_FALSE(contains(outOfRange, "fileB"));
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

std::string describeDefines(const ShaderDefines& defines) {
  std::string out;
  for (const pbr::ShaderDefine& d : defines) out += d.name + "=" + d.value + " ";
  return out;
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
  // Every model x culling x stats with the standard PBR terms, then every form of every PBR term once.
  DefineSets lighting, ibl;
  for (const pbr::ShadingModel model : {pbr::ShadingModel::Pbr, pbr::ShadingModel::BlinnPhong}) {
    for (const bool clustered : {false, true}) {
      for (const bool stats : {false, true}) {
        pbr::LightingOptions options;
        options.model = model;
        options.stats = stats;
        lighting.push_back(pbr::LightingPass::permutation(options, clustered, GL_RGBA16F));
        // The IBL permutations exist for PBR only (LightingPass never asks for them with Blinn-Phong).
        const pbr::EnvironmentMaps maps;
        options.environment = &maps;
        if (model == pbr::ShadingModel::Pbr) ibl.push_back(pbr::LightingPass::permutation(options, clustered, GL_RGBA16F));
      }
    }
  }
  for (const char* variant : {"visibility=hammon", "visibility=separable", "ndf=beckmann", "fresnel=exact",
                              "fresnel=schlick-sg", "diffuse=lambert", "diffuse=burley", "diffuse=lambert-1-f-vh"}) {
    pbr::LightingOptions options;
    options.variant = pbr::parseShadingVariant(variant);
    lighting.push_back(pbr::LightingPass::permutation(options, true, GL_RGBA16F));
  }
  checkComputeCompiles("lighting/deferred.comp", lighting);
  checkComputeCompiles("lighting/deferred.comp", ibl);
  checkComputeCompiles("lighting/cluster_assign.comp", flagCombinations({"ASSIGN_FILL", "ASSIGN_STATS"}));
  checkComputeCompiles("lighting/cluster_scan.comp", flagCombinations({"ASSIGN_STATS"}));
  checkComputeCompiles("lighting/cluster_bounds.comp", DefineSets{ShaderDefines{}});
  checkComputeCompiles("lighting/cluster_lights.comp", DefineSets{ShaderDefines{}});
  checkComputeCompiles("lighting/cluster_tiles.comp", DefineSets{ShaderDefines{}});
  checkComputeCompiles("lighting/cluster_debug.comp", flagCombinations({"DEBUG_SLICES"}));
  for (const char* channel : {"GBUFFER_CHANNEL_BASE_COLOR", "GBUFFER_CHANNEL_NORMAL", "GBUFFER_CHANNEL_ROUGHNESS",
                              "GBUFFER_CHANNEL_METALNESS", "GBUFFER_CHANNEL_DEPTH"}) {
    checkComputeCompiles("lighting/gbuffer_debug.comp", DefineSets{ShaderDefines{{channel, "1"}}});
  }
  checkComputeCompiles("post/post.comp", DefineSets{ShaderDefines{}}, pbr::bindingDefines({pbr::kPostUbo}));
  const ShaderLibrary shaders;
  const std::vector<std::string> gbufferFlags = {"BASE_COLOR_MAP", "METALLIC_ROUGHNESS_MAP", "NORMAL_MAP",
                                                 "OCCLUSION_MAP", "EMISSIVE_MAP", "ALPHA_MASK"};
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
}

namespace {

std::string readText(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  REQUIRE_MESSAGE(in, "cannot open " << path);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace

TEST_CASE("shader library: every binding point a shader names comes from a binding table, and tables do not collide") {
  // The names GLSL reads in layout(binding = NAME): each must be a define of the table its module compiles with.
  std::set<std::string> declared;
  for (const ShaderDefines& table : {pbr::lightingBindingDefines(), pbr::gbufferBindingDefines(),
                                     pbr::bindingDefines({pbr::kPostUbo}), pbr::bindingDefines({pbr::kBrdfGridSsbo})}) {
    for (const pbr::ShaderDefine& d : table) declared.insert(d.name);
  }
  static const std::regex named(R"(binding\s*=\s*([A-Z_][A-Z0-9_]*))");
  size_t uses = 0;
  for (const auto& entry : fs::recursive_directory_iterator(fs::path(PBR_SOURCE_DIR) / "shaders")) {
    if (!entry.is_regular_file()) continue;
    const std::string text = readText(entry.path());
    for (std::sregex_iterator it(text.begin(), text.end(), named), end; it != end; ++it, ++uses) {
      CAPTURE(entry.path().string());
      CHECK_MESSAGE(declared.count((*it)[1].str()) == 1, (*it)[1].str() << " is in no binding table");
    }
  }
  CHECK(uses > 20);
  // Points bound together must not share an index within a kind; different kinds may.
  CHECK_THROWS_WITH_AS(pbr::bindingDefines({pbr::kFrameUbo, {"OTHER_UBO", pbr::BindingKind::UniformBuffer, 0}}),
                       "binding points FRAME_UBO and OTHER_UBO share index 0", std::logic_error);
  CHECK_NOTHROW(pbr::bindingDefines({pbr::kFrameUbo, {"SOME_SSBO", pbr::BindingKind::StorageBuffer, 0}}));
  CHECK_THROWS_WITH_AS(pbr::bindingDefines({pbr::kFrameUbo, pbr::kFrameUbo}), "binding point FRAME_UBO is declared twice",
                       std::logic_error);
}

TEST_CASE("shader library: brdf.glsl tests exactly the defines that name the PBR variant's terms") {
  // A define the C++ table names but brdf.glsl never tests would shade the default form without a word.
  const std::string glsl = readText(fs::path(PBR_SOURCE_DIR) / "shaders/lighting/brdf.glsl");
  std::set<std::string> tested;
  const std::regex definedName(R"(defined\((\w+)\))");
  for (std::sregex_iterator it(glsl.begin(), glsl.end(), definedName), end; it != end; ++it) tested.insert((*it)[1]);
  const std::vector<std::string> names = pbr::variantDefineNames();
  CHECK(std::set<std::string>(names.begin(), names.end()).size() == names.size());
  CHECK(std::set<std::string>(names.begin(), names.end()) == tested);

  // The same for the Blinn-Phong model's lobe.
  const std::string phong = readText(fs::path(PBR_SOURCE_DIR) / "shaders/lighting/model_blinn_phong.glsl");
  std::set<std::string> phongTested;
  for (std::sregex_iterator it(phong.begin(), phong.end(), definedName), end; it != end; ++it) {
    phongTested.insert((*it)[1]);
  }
  const std::vector<std::string> lobes = pbr::blinnPhongDefineNames();
  CHECK(std::set<std::string>(lobes.begin(), lobes.end()) == phongTested);

  // Every variant, one define per term, and no two variants share a permutation.
  std::set<std::string> permutations;
  size_t variants = 0;
  for (const char* vis : {"exact", "hammon", "separable"}) {
    for (const char* ndf : {"ggx", "beckmann"}) {
      for (const char* fresnel : {"schlick", "exact", "schlick-sg"}) {
        for (const char* diffuse : {"lambert-1-f", "lambert", "burley", "lambert-1-f-vh"}) {
          const std::string text = std::string("visibility=") + vis + ",ndf=" + ndf + ",fresnel=" + fresnel +
                                   ",diffuse=" + diffuse;
          const ShaderDefines defines = pbr::shaderDefines(pbr::parseShadingVariant(text));
          CAPTURE(text);
          CHECK(defines.size() == 4);
          pbr::LightingOptions options;
          options.variant = pbr::parseShadingVariant(text);
          permutations.insert(describeDefines(pbr::LightingPass::permutation(options, true, GL_RGBA16F)));
          ++variants;
        }
      }
    }
  }
  CHECK(permutations.size() == variants);
}
