// The renderer's declared pass list: the order each configuration runs and what each pass reads.
#include <doctest/doctest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "core/builtin_scenes.hpp"
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
