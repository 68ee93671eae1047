#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "core/scene/builtin_scenes.hpp"
#include "lighting/light_clusters.hpp"
#include "lighting/lighting_pass.hpp"
#include "tests/cluster_test_scene.hpp"
#include "tests/gl_test_context.hpp"
#include "tests/render_util.hpp"

using namespace pbr;

namespace {

const glm::ivec2 kSize{160, 90};

using test::clusterScene;

std::vector<PointLight> randomLights(int count, uint64_t seed) {
  RandomLightSpec spec;
  spec.count = count;
  spec.seed = seed;
  spec.boundsMin = {-12.0f, 0.05f, -30.0f};
  spec.boundsMax = {12.0f, 4.0f, 8.0f};
  spec.radiusMin = 0.5f;
  spec.radiusMax = 4.0f;
  spec.powerMin = 2.0f;
  spec.powerMax = 40.0f;
  return makeRandomLights(spec);
}

// The awkward cases: straddling the near plane, behind the camera, covering the whole view, radius 0, and
// centred exactly on slice boundaries along the view axis.
std::vector<PointLight> edgeCaseLights(const Scene& s, const ClusterConfig& config) {
  const Camera& c = s.camera;
  const glm::vec3 forward = glm::normalize(c.target - c.position);
  std::vector<PointLight> lights = {
      {c.position + forward * c.nearPlane, 1.0f, {1.0f, 0.9f, 0.8f}, 30.0f},
      {c.position - forward * 2.0f, 5.0f, {0.5f, 0.5f, 1.0f}, 60.0f},
      {c.target, 500.0f, {0.2f, 0.2f, 0.2f}, 5.0f},
      {glm::vec3(0.5f, 0.3f, 1.0f), 0.0f, {1.0f, 0.0f, 0.0f}, 100.0f},
  };
  for (int k : {1, 5, 10, 12}) {
    const float depth = clusterSliceDepth(c.nearPlane, c.farPlane, k, config.slices);
    lights.push_back({c.position + forward * depth, 1.5f + 0.1f * k, {0.3f, 1.0f, 0.4f}, 20.0f});
  }
  return lights;
}

// Renders the scene by brute force and clustered, checks the two agree, and returns the clustered frame.
test::RenderedFrame checkClusteredMatchesBruteForce(const Scene& scene, ShadingModel model,
                                                    const ClusterConfig& config = {}, glm::ivec2 size = kSize) {
  FrameOptions options;
  options.model = model;
  options.culling = Culling::None;
  const test::RenderedFrame reference = test::renderScene(scene, size, options, 1);
  options.culling = Culling::Clustered;
  test::RenderedFrame clustered = test::renderScene(scene, size, options, 2, config);
  CAPTURE(scene.lights.size());
  CAPTURE(toString(model));
  CHECK(clustered.stats.overflowedClusters == 0);
  CHECK(test::maxRelativeDifference(clustered.hdr, reference.hdr) <= 1e-5);
  CHECK(test::countDifferentBytes(clustered.ldr, reference.ldr) == 0);
  return clustered;
}

}  // namespace

TEST_CASE("clusters: clustered equals brute force for 0, 1, 64, 1024 and 20000 lights") {
  PBR_REQUIRE_GL();
  const ClusterConfig config;
  for (int count : {0, 1, 64, 1024, 20000}) {
    Scene scene = clusterScene();
    scene.lights = randomLights(count, 7u + static_cast<uint64_t>(count));
    checkClusteredMatchesBruteForce(scene, ShadingModel::Pbr, config);
  }
}

TEST_CASE("clusters: the frame does not depend on the order in which the scene lists its lights") {
  PBR_REQUIRE_GL();
  Scene scene = clusterScene();
  scene.lights = randomLights(2000, 31);
  // Lights in one place that differ only in colour: their order in the buffer is still the same.
  scene.lights.push_back({glm::vec3(0.5f, 0.6f, 0.5f), 3.0f, {1.0f, 0.2f, 0.1f}, 30.0f});
  scene.lights.push_back({glm::vec3(0.5f, 0.6f, 0.5f), 3.0f, {0.1f, 0.2f, 1.0f}, 30.0f});
  FrameOptions options;
  const test::RenderedFrame listed = test::renderScene(scene, kSize, options);
  std::reverse(scene.lights.begin(), scene.lights.end());
  std::rotate(scene.lights.begin(), scene.lights.begin() + 700, scene.lights.end());
  const test::RenderedFrame reordered = test::renderScene(scene, kSize, options);
  CHECK(listed.stats.overflowedClusters == 0);
  CHECK(test::maxRelativeDifference(reordered.hdr, listed.hdr) == 0.0);
  CHECK(test::countDifferentBytes(reordered.ldr, listed.ldr) == 0);
}

TEST_CASE("clusters: edge-case lights agree with brute force in both shading models") {
  PBR_REQUIRE_GL();
  ClusterConfig config;
  config.tileSize = 16;
  Scene scene = clusterScene();
  scene.lights = edgeCaseLights(scene, config);
  const std::vector<PointLight> extra = randomLights(200, 99);
  scene.lights.insert(scene.lights.end(), extra.begin(), extra.end());
  checkClusteredMatchesBruteForce(scene, ShadingModel::Pbr, config);
  checkClusteredMatchesBruteForce(scene, ShadingModel::BlinnPhong, config);
}

TEST_CASE("clusters: lights that together pass an invocation's loop budget finish in a workgroup of their own") {
  PBR_REQUIRE_GL();
  ClusterConfig config;
  config.tileSize = 16;  // 10 x 6 tiles
  Scene scene = clusterScene();
  // Around the eye, so every tile, reaching slice 115 of 192: 60 tiles x 2 x (116 - 0 + 2) = 14160 candidates
  // each (cluster_lights.comp), under the 16384 of one light; three of them fill the 49152 of an invocation of
  // four lights, so its fourth light is visited by the workgroup path.
  const float depth = clusterSliceDepth(scene.camera.nearPlane, scene.camera.farPlane, 115, config.slices) * 1.01f;
  for (int i = 0; i < 8; ++i) {
    scene.lights.push_back({scene.camera.position, depth, {1.0f, 0.2f * i, 0.5f}, 3.0f + i});
  }
  const std::vector<PointLight> extra = randomLights(100, 11);
  scene.lights.insert(scene.lights.end(), extra.begin(), extra.end());
  checkClusteredMatchesBruteForce(scene, ShadingModel::Pbr, config);
}

TEST_CASE("clusters: 65536 lights with one cluster touched by every light render without loss") {
  PBR_REQUIRE_GL();
  Scene scene = clusterScene();
  RandomLightSpec spec;
  spec.count = 65536;
  spec.seed = 3;
  // Every sphere contains the point (0, 0, 0) of the floor in front of the camera, so the cluster holding it
  // lists all of them.
  spec.boundsMin = {-0.3f, -0.3f, -0.3f};
  spec.boundsMax = {0.3f, 0.3f, 0.3f};
  spec.radiusMin = 0.7f;
  spec.radiusMax = 2.0f;
  spec.powerMin = 0.001f;
  spec.powerMax = 0.01f;
  scene.lights = makeRandomLights(spec);
  const test::RenderedFrame clustered = checkClusteredMatchesBruteForce(scene, ShadingModel::Pbr, {}, {96, 54});
  CHECK(clustered.stats.maxPerCluster == 65536);
}

TEST_CASE("clusters: an index list over its memory limit falls back to brute force for the clusters that do not fit") {
  PBR_REQUIRE_GL();
  Scene scene = clusterScene();
  scene.lights = randomLights(2048, 5);
  ClusterConfig tiny;
  tiny.maxIndexBytes = 4096;
  FrameOptions options;
  options.culling = Culling::None;
  const test::RenderedFrame reference = test::renderScene(scene, kSize, options, 1);
  options.culling = Culling::Clustered;
  const test::RenderedFrame clustered = test::renderScene(scene, kSize, options, 2, tiny);
  CHECK(clustered.stats.overflowedClusters > 0);
  CHECK(clustered.stats.indexEntries > 1024);
  CHECK(test::maxRelativeDifference(clustered.hdr, reference.hdr) <= 1e-5);
  CHECK(test::countDifferentBytes(clustered.ldr, reference.ldr) == 0);
}

TEST_CASE("clusters: 1000 random spot cones, narrow and wide, seen from inside and across the near plane, equal brute force") {
  PBR_REQUIRE_GL();
  ClusterConfig config;
  config.tileSize = 16;
  Scene scene = clusterScene();
  RandomLightSpec spec;
  spec.count = 1000;
  spec.seed = 5;
  spec.boundsMin = {-12.0f, 0.05f, -30.0f};
  spec.boundsMax = {12.0f, 4.0f, 8.0f};
  spec.radiusMin = 0.5f;
  spec.radiusMax = 6.0f;
  spec.powerMin = 2.0f;
  spec.powerMax = 60.0f;
  spec.spotShare = 0.8f;
  scene.lights = makeRandomLights(spec);
  // The awkward cones: one holding the camera, one straddling the near plane aimed across the view, one as wide as
  // glTF allows covering the whole view, a needle of 1 degree, and one of zero range.
  const Camera& c = scene.camera;
  const glm::vec3 forward = glm::normalize(c.target - c.position);
  const auto cone = [](glm::vec3 direction, float innerDeg, float outerDeg) {
    return SpotCone{glm::normalize(direction), glm::radians(innerDeg), glm::radians(outerDeg)};
  };
  scene.lights.push_back({c.position - forward * 2.0f, 8.0f, {1.0f, 0.9f, 0.8f}, 80.0f, cone(forward, 10.0f, 30.0f)});
  scene.lights.push_back({c.position + forward * c.nearPlane, 3.0f, {0.4f, 0.6f, 1.0f}, 40.0f,
                          cone({1.0f, -0.4f, 0.0f}, 0.0f, 50.0f)});
  scene.lights.push_back({c.target + glm::vec3(0.0f, 3.0f, 0.0f), 500.0f, {0.2f, 0.2f, 0.2f}, 5.0f,
                          cone({0.0f, -1.0f, 0.0f}, 80.0f, 90.0f)});
  scene.lights.push_back({glm::vec3(0.0f, 3.0f, 0.0f), 6.0f, {1.0f, 1.0f, 0.2f}, 200.0f, cone({0.1f, -1.0f, 0.2f}, 0.5f, 1.0f)});
  scene.lights.push_back({glm::vec3(0.5f, 0.3f, 1.0f), 0.0f, {1.0f, 0.0f, 0.0f}, 100.0f, cone({0.0f, -1.0f, 0.0f}, 5.0f, 20.0f)});
  const auto spots = std::count_if(scene.lights.begin(), scene.lights.end(), [](const PointLight& l) { return l.spot.has_value(); });
  CHECK(spots > 700);
  CHECK(size_t(spots) < scene.lights.size());
  checkClusteredMatchesBruteForce(scene, ShadingModel::Pbr, config);
  checkClusteredMatchesBruteForce(scene, ShadingModel::BlinnPhong, config);
  // Culled as cones: each contributing pair on both paths alike, and a small share of brute force's pairs.
  FrameOptions options;
  options.stats = true;
  options.culling = Culling::None;
  const test::RenderedFrame brute = test::renderScene(scene, kSize, options, 1);
  options.culling = Culling::Clustered;
  const test::RenderedFrame clustered = test::renderScene(scene, kSize, options, 2, config);
  CHECK(brute.stats.pairs.contributing == clustered.stats.pairs.contributing);
  CHECK(clustered.stats.pairs.contributing > 0);
  CHECK(clustered.stats.pairs.evaluated * 20 < brute.stats.pairs.evaluated);
}

TEST_CASE("clusters: statistics count contributing pairs identically on both paths and culling helps") {
  PBR_REQUIRE_GL();
  Scene scene = clusterScene();
  scene.lights = randomLights(1024, 11);
  FrameOptions options;
  options.stats = true;
  options.culling = Culling::None;
  const test::RenderedFrame brute = test::renderScene(scene, kSize, options, 1);
  options.culling = Culling::Clustered;
  const test::RenderedFrame clustered = test::renderScene(scene, kSize, options, 2);
  CHECK(brute.stats.pairs.contributing == clustered.stats.pairs.contributing);
  CHECK(clustered.stats.pairs.contributing > 0);
  CHECK(clustered.stats.pairs.evaluated < brute.stats.pairs.evaluated / 4);
  CHECK(clustered.stats.cullingEfficiency() > brute.stats.cullingEfficiency());
  CHECK(clustered.stats.visibleLights > 0);
  CHECK(clustered.stats.visibleLights < 1024);
  CHECK(clustered.stats.nonEmptyClusters > 0);
  CHECK(clustered.stats.indexEntries >= clustered.stats.maxPerCluster);
}

TEST_CASE("clusters: 300000 lights on a small frame equal brute force") {
  PBR_REQUIRE_GL();
  Scene scene = clusterScene();
  scene.lights = randomLights(300000, 17);
  for (PointLight& l : scene.lights) l.luminousPower *= 0.002f;  // keep the sum of 300,000 lights in range
  const std::vector<PointLight> edges = edgeCaseLights(scene, ClusterConfig{});
  scene.lights.insert(scene.lights.begin() + 1000, edges.begin(), edges.end());
  checkClusteredMatchesBruteForce(scene, ShadingModel::Pbr, {}, {48, 27});
}

// Over kLightsPerDispatch lights the lighting pass loops in several dispatches, and over kAssignChunkLights the
// count and fill passes do; a third of these lights reach one point, so its cluster lists more than either.
TEST_CASE("clusters: 1048576 lights, one cluster listing a third of them, equal chunked brute force") {
  PBR_REQUIRE_GL();
  Scene scene = clusterScene();
  std::vector<PointLight> lights = randomLights(1 << 20, 29);
  RandomLightSpec near;
  near.count = static_cast<int>(lights.size() / 3);
  near.seed = 31;
  // Every sphere contains the point (0, 0, 0) of the floor in front of the camera.
  near.boundsMin = {-0.3f, -0.3f, -0.3f};
  near.boundsMax = {0.3f, 0.3f, 0.3f};
  near.radiusMin = 0.7f;
  near.radiusMax = 2.0f;
  const std::vector<PointLight> reaching = makeRandomLights(near);
  for (size_t i = 0; i < reaching.size(); ++i) lights[3 * i + 1] = reaching[i];
  const std::vector<PointLight> edges = edgeCaseLights(scene, ClusterConfig{});
  std::copy(edges.begin(), edges.end(), lights.begin() + 500000);
  for (PointLight& l : lights) l.luminousPower *= 1e-4f;
  scene.lights = std::move(lights);
  REQUIRE(scene.lights.size() == 1048576);
  REQUIRE(scene.lights.size() > 3 * kLightsPerDispatch);
  REQUIRE(scene.lights.size() / 3 > kLightsPerDispatch);
  const test::RenderedFrame clustered = checkClusteredMatchesBruteForce(scene, ShadingModel::Pbr, {}, {24, 14});
  CHECK(clustered.stats.maxPerCluster > scene.lights.size() / 3);
}

TEST_CASE("clusters: a frame seeing only sky holds no active cluster and renders the background alone") {
  PBR_REQUIRE_GL();
  Scene scene = clusterScene();
  scene.camera.target = scene.camera.position + glm::vec3(0.0f, 1.0f, -0.2f);  // up, away from every surface
  scene.lights = randomLights(4096, 7);
  FrameOptions options;
  options.stats = true;
  options.culling = Culling::Clustered;
  const test::RenderedFrame clustered = test::renderScene(scene, kSize, options, 2);
  CHECK(clustered.stats.activeClusters == 0);
  CHECK(clustered.stats.indexEntries == 0);
  CHECK(clustered.stats.pairs.evaluated == 0);
  size_t nonBlack = 0;
  for (size_t i = 0; i < clustered.hdr.pixels.size(); i += 4) {
    nonBlack += clustered.hdr.pixels[i] != 0.0f || clustered.hdr.pixels[i + 1] != 0.0f || clustered.hdr.pixels[i + 2] != 0.0f;
  }
  CHECK(nonBlack == 0);
  options.culling = Culling::None;
  const test::RenderedFrame reference = test::renderScene(scene, kSize, options, 1);
  CHECK(test::countDifferentBytes(clustered.ldr, reference.ldr) == 0);
}
