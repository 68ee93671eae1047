// Tests of the shader library that need no driver (pbr::ShaderSources): #include resolution and its errors on a
// scratch shader tree, the #line bookkeeping that maps log lines back to files, and the binding numbers and define
// names shared between GLSL and C++.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/scene/binding_table.hpp"
#include "core/scene/frame_block.hpp"
#include "core/scene/shader_sources.hpp"
#include "core/scene/shading_model.hpp"
#include "gbuffer/gbuffer_bindings.hpp"
#include "lighting/lighting_bindings.hpp"
#include "lighting/lighting_options.hpp"
#include "post/post_bindings.hpp"
#include "tests/shader_tree.hpp"

namespace fs = std::filesystem;
using namespace pbr;
using namespace pbr::test;

namespace {

std::string readText(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  REQUIRE_MESSAGE(in, "cannot open " << path);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

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

  const ShaderSources lib(tree.root());
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

TEST_CASE("shader library: include cycles, missing includes and a missing #version are errors naming file:line") {
  const TempShaderTree tree;
  tree.write("cycle.comp", std::string(kComputeHeader) + "#include \"a.glsl\"\n");
  tree.write("a.glsl", "// a\n#include \"b.glsl\"\n");
  tree.write("b.glsl", "// b\n// b\n#include \"a.glsl\"\n");
  tree.write("missing.comp", std::string(kComputeHeader) + "#include \"inc/has_missing.glsl\"\n");
  tree.write("inc/has_missing.glsl", "// first\n#include \"nowhere/gone.glsl\"\n");
  tree.write("noversion.comp", "// a comment before the version\n#version 450 core\nvoid main() {}\n");
  const ShaderSources lib(tree.root());

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

TEST_CASE("shader library: every binding point a shader names comes from a binding table, and tables do not collide") {
  // The names GLSL reads in layout(binding = NAME): each must be a define of the table its module compiles with.
  std::set<std::string> declared;
  for (const ShaderDefines& table : {pbr::lightingBindingDefines(), pbr::gbufferBindingDefines(),
                                     pbr::forwardBindingDefines({}),
                                     pbr::bindingDefines({pbr::kPostUbo, pbr::kExposureSsbo, pbr::kFxaaEdgesSsbo}),
                                     pbr::bindingDefines({pbr::kBrdfGridSsbo})}) {
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
          permutations.insert(describeDefines(pbr::lightingPermutation(options, true, pbr::HdrFormat::Rgba16f)));
          ++variants;
        }
      }
    }
  }
  CHECK(permutations.size() == variants);
}

TEST_CASE("shader library: a program's label names its files and the defines that choose its permutation") {
  // Switches on by name, other values as NAME=value; switches off and binding points are left out.
  const ShaderDefines defines = concat({{"CLUSTERED", "1"}, {"LIGHTING_STATS", "0"}, {"HDR_IMAGE_FORMAT", "rgba16f"}},
                                       bindingDefines({kFrameUbo}));
  CHECK(programLabel("lighting/deferred.comp", defines) ==
        "lighting/deferred.comp [CLUSTERED HDR_IMAGE_FORMAT=rgba16f]");
  CHECK(programLabel("post/fxaa.comp", {}) == "post/fxaa.comp");
  CHECK(programLabel("post/post.comp", bindingDefines({kFrameUbo})) == "post/post.comp");
}
