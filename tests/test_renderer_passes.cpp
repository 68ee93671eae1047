// The renderer's declared pass list: the order each configuration runs and what each pass reads.
#include <doctest/doctest.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "core/scene/builtin_scenes.hpp"
#include "renderer/pass_list.hpp"
#include "renderer/renderer.hpp"
#include "tests/gl_test_context.hpp"

using namespace pbr;
using R = FrameResource;

namespace {

std::vector<std::string> names(const PassList& passes) {
  std::vector<std::string> out;
  for (const FramePass& p : passes) out.push_back(p.name);
  return out;
}

}  // namespace

TEST_CASE("pass list: the renderer declares each configuration's passes in order, IBL as an input of lighting") {
  PBR_REQUIRE_GL();
  const ShaderLibrary shaders;
  const Scene scene = makeBuiltinScene("default");
  Renderer renderer(shaders, scene, 64, 36);

  FrameOptions options;
  CHECK(names(renderer.passList(options)) == std::vector<std::string>{"gbuffer", "cluster", "lighting", "post"});
  const PassList clustered = renderer.passList(options);
  CHECK((clustered[2].reads == std::vector<R>{R::GBuffer, R::Radiance, R::Lights, R::Camera, R::ClusterLists}));

  options.culling = Culling::None;
  options.debug = DebugChannel::Normal;
  options.aa = AntiAliasing::Fxaa;  // a channel that replaces the frame is not anti-aliased
  ImageRgba8 ldr;
  // A surface channel draws the G-buffer over every display pixel: neither lighting nor post is run for it.
  CHECK(names(renderer.passList(options, {&ldr, nullptr})) ==
        std::vector<std::string>{"gbuffer", "debug", "readback"});
  // Without the cluster grid the cluster views are left out.
  options.debug = DebugChannel::Slices;
  CHECK(names(renderer.passList(options)) == std::vector<std::string>{"gbuffer", "lighting", "post", "aa"});
  // The efficiency view reads the lighting pass's per-pixel pair counts, brute force too.
  options.debug = DebugChannel::Efficiency;
  const PassList efficiency = renderer.passList(options);
  CHECK(names(efficiency) == std::vector<std::string>{"gbuffer", "lighting", "debug"});
  CHECK((efficiency[1].writes == std::vector<R>{R::Radiance, R::PairCounts}));
  CHECK((efficiency[2].reads == std::vector<R>{R::PairCounts, R::Camera}));
  // Emission is post's picture of the radiance the geometry pass wrote: no lighting pass.
  options.debug = DebugChannel::Emission;
  CHECK(names(renderer.passList(options)) == std::vector<std::string>{"gbuffer", "post", "debug"});

  // The cluster views are painted over the anti-aliased frame, so that their legend is not filtered.
  options.culling = Culling::Clustered;
  options.debug = DebugChannel::Slices;
  CHECK(names(renderer.passList(options)) ==
        std::vector<std::string>{"gbuffer", "cluster", "lighting", "post", "aa", "debug"});

  // A scene with an environment: the lighting pass reads the maps, for PBR only.
  Scene lit = scene;
  lit.environment = EnvironmentDesc{};
  Renderer withSky(shaders, lit, 64, 36);
  const PassList pbrPasses = withSky.passList(FrameOptions{});
  CHECK((pbrPasses[2].reads.back() == R::Environment));
  FrameOptions blinnPhong;
  blinnPhong.model = ShadingModel::BlinnPhong;
  const PassList bpPasses = withSky.passList(blinnPhong);
  CHECK((bpPasses[2].reads.back() == R::ClusterLists));
}

TEST_CASE("pass list: BLEND surfaces add a transparency pass after lighting, and only they do") {
  PBR_REQUIRE_GL();
  const ShaderLibrary shaders;
  Scene scene = makeBuiltinScene("default");
  FrameOptions options;
  {
    // The default scene has no BLEND material: the frame is as before, with no pass for transparency.
    Renderer renderer(shaders, scene, 64, 36);
    CHECK(names(renderer.passList(options)) == std::vector<std::string>{"gbuffer", "cluster", "lighting", "post"});
  }
  scene.objects.back().material.alphaMode = AlphaMode::Blend;
  scene.objects.back().material.alpha = 0.5f;
  Renderer renderer(shaders, scene, 64, 36);
  const PassList passes = renderer.passList(options);
  CHECK(names(passes) == std::vector<std::string>{"gbuffer", "cluster", "lighting", "transparency", "post"});
  // The clusters the BLEND surfaces reach get lists: the cluster pass draws their geometry too.
  CHECK((passes[1].reads == std::vector<R>{R::Lights, R::Camera, R::GBuffer, R::Geometry}));
  CHECK((passes[3].reads ==
         std::vector<R>{R::GBuffer, R::Radiance, R::Lights, R::Camera, R::ClusterLists, R::Geometry}));
  CHECK((passes[3].writes == std::vector<R>{R::Radiance}));
  // A channel that replaces the frame draws no transparency.
  options.debug = DebugChannel::Efficiency;
  CHECK(names(renderer.passList(options)) == std::vector<std::string>{"gbuffer", "cluster", "lighting", "debug"});
}

TEST_CASE("pass list: each debug channel's row decides its passes: a channel that replaces the display has no post") {
  PBR_REQUIRE_GL();
  const ShaderLibrary shaders;
  const Scene scene = makeBuiltinScene("transparency");  // BLEND surfaces, for the layers channel
  Renderer renderer(shaders, scene, 64, 36);
  for (const DebugChannel channel : kDebugChannels) {
    const DebugChannelInfo& row = debugChannelInfo(channel);
    CAPTURE(row.name);
    CHECK(std::string(toString(channel)) == row.name);
    CHECK(isGBufferChannel(channel) == (row.gbufferDefine != nullptr));
    FrameOptions options;
    options.debug = channel;
    options.shadows.mode = ShadowMode::On;  // every light casts, for the shadows channel
    options.autoExposure = true;
    const std::vector<std::string> passes = names(renderer.passList(options));
    const auto has = [&](const char* name) { return std::count(passes.begin(), passes.end(), name) == 1; };
    CHECK(has("debug"));
    CHECK(has("post") == !row.replacesDisplay);
    CHECK(has("exposure") == !row.replacesDisplay);
    const bool unlit = row.source == DebugSource::Surface || row.source == DebugSource::Emission ||
                       row.source == DebugSource::Layers;
    CHECK(has("lighting") == !unlit);
    CHECK(has("shadow") == !unlit);
  }
}

namespace {

// A pass's row of docs/architecture.md's table: what it reads and writes, required (plain) and optional ([...]).
struct DocumentedPass {
  std::set<std::string> reads, optionalReads, writes, optionalWrites;
};

void parseCell(const std::string& cell, std::set<std::string>& required, std::set<std::string>& optional) {
  std::istringstream items(cell);
  for (std::string item; std::getline(items, item, ',');) {
    item.erase(0, item.find_first_not_of(' '));
    item.erase(item.find_last_not_of(' ') + 1);
    if (item.size() > 2 && item.front() == '[' && item.back() == ']') {
      optional.insert(item.substr(1, item.size() - 2));
    } else {
      required.insert(item);
    }
  }
}

std::map<std::string, DocumentedPass> documentedPasses() {
  std::ifstream doc(std::string(PBR_SOURCE_DIR) + "/docs/architecture.md");
  std::map<std::string, DocumentedPass> passes;
  bool inSection = false;  // the table of the section "The frame's pass list"
  for (std::string line; std::getline(doc, line);) {
    if (line.rfind("## ", 0) == 0) inSection = line == "## The frame's pass list";
    if (!inSection || line.rfind("| `", 0) != 0) continue;
    std::vector<std::string> cells;
    std::istringstream row(line.substr(1));
    for (std::string cell; std::getline(row, cell, '|');) cells.push_back(cell);
    if (cells.size() < 3) continue;
    const std::string name = cells[0].substr(cells[0].find('`') + 1, cells[0].rfind('`') - cells[0].find('`') - 1);
    DocumentedPass& p = passes[name];
    parseCell(cells[1], p.reads, p.optionalReads);
    parseCell(cells[2], p.writes, p.optionalWrites);
  }
  return passes;
}

void checkAgainst(const std::set<std::string>& required, const std::set<std::string>& optional,
                  const std::vector<R>& actual) {
  std::set<std::string> names;
  for (const R r : actual) names.insert(toString(r));
  for (const std::string& r : required) CHECK_MESSAGE(names.count(r) == 1, "missing " << r);
  for (const std::string& r : names) CHECK_MESSAGE(required.count(r) + optional.count(r) == 1, "undocumented " << r);
}

}  // namespace

TEST_CASE("pass list: every pass of the renderer reads and writes what docs/architecture.md's table says") {
  PBR_REQUIRE_GL();
  const std::map<std::string, DocumentedPass> documented = documentedPasses();
  REQUIRE(documented.size() >= 10);
  const ShaderLibrary shaders;
  Scene lit = makeBuiltinScene("transparency");
  lit.environment = EnvironmentDesc{};
  Renderer renderer(shaders, lit, 64, 36);
  std::vector<FrameOptions> configurations;
  for (const Culling culling : {Culling::Clustered, Culling::None}) {
    FrameOptions options;
    options.culling = culling;
    options.shadows.mode = ShadowMode::On;
    options.aa = AntiAliasing::Fxaa;
    options.autoExposure = true;
    configurations.push_back(options);
    for (const DebugChannel channel : kDebugChannels) {
      options.debug = channel;
      configurations.push_back(options);
    }
  }
  ImageRgba8 ldr;
  ImageRgbaF hdr;
  std::set<std::string> seen;
  for (const FrameOptions& options : configurations) {
    for (const FramePass& pass : renderer.passList(options, {&ldr, &hdr})) {
      CAPTURE(pass.name);
      CAPTURE(options.debug ? toString(*options.debug) : "no debug channel");
      seen.insert(pass.name);
      const auto row = documented.find(pass.name);
      REQUIRE(row != documented.end());
      checkAgainst(row->second.reads, row->second.optionalReads, pass.reads);
      checkAgainst(row->second.writes, row->second.optionalWrites, pass.writes);
    }
  }
  // The table names no pass the renderer never runs.
  for (const auto& [name, row] : documented) CHECK_MESSAGE(seen.count(name) == 1, name << " never ran");
}
