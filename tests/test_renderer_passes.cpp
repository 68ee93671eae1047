// The renderer's declared pass list: the order each configuration runs and what each pass reads.
#include <doctest/doctest.h>

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
  options.gbufferView = GBufferChannel::Normal;
  ImageRgba8 ldr;
  CHECK(names(renderer.passList(options, {&ldr, nullptr})) ==
        std::vector<std::string>{"gbuffer", "lighting", "post", "gbuffer view", "readback"});

  options.culling = Culling::Clustered;
  options.gbufferView.reset();
  options.debugView = ClusterDebugView::Slices;
  CHECK(names(renderer.passList(options)) ==
        std::vector<std::string>{"gbuffer", "cluster", "lighting", "post", "debug"});

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
