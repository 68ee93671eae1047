#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include <glm/gtc/matrix_transform.hpp>

#include "renderer/renderer.hpp"
#include "core/scene/builtin_scenes.hpp"
#include "core/scene/frame_block.hpp"
#include "tests/gl_test_context.hpp"

using namespace pbr;

namespace {

struct Box {
  glm::dvec3 lo{1e300}, hi{-1e300};
  bool empty() const { return lo.x > hi.x; }
};

// The surface points of the frame, from its depth buffer in double precision, with the clusters and tiles the
// clustering contract puts them in: screen tiles of `tile` pixels x exponential slices z_k = near (far/near)^(k/S).
// A point within 2e-3 (in slice units) of a slice boundary is `borderline`: the GPU puts it in both slices.
struct SurfacePoint {
  glm::dvec3 view;
  size_t cluster, tile;
  bool borderline;
};

std::vector<SurfacePoint> surfacePoints(const Renderer& renderer, const Camera& cam, int width, int height, int tile,
                                        int slices) {
  std::vector<float> depth(size_t(width) * height);
  glGetTextureImage(renderer.gbuffer().depth.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                    static_cast<GLsizei>(depth.size() * sizeof(float)), depth.data());
  const glm::vec4 proj = makeFrameBlock(cam, width, height).projParams;
  const int tilesX = (width + tile - 1) / tile, tilesY = (height + tile - 1) / tile;
  const double scale = slices / std::log(double(cam.farPlane) / cam.nearPlane);
  std::vector<SurfacePoint> points;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const double d = depth[size_t(y) * width + x];
      if (d <= 0.0) continue;
      const double viewDepth = double(proj.w) / (d + proj.z);
      const double ndcX = (x + 0.5) / width * 2 - 1, ndcY = (y + 0.5) / height * 2 - 1;
      const glm::dvec3 view(viewDepth * ndcX / proj.x, viewDepth * ndcY / proj.y, -viewDepth);
      const double s = std::log(viewDepth / cam.nearPlane) * scale;
      const size_t column = size_t(y / tile) * tilesX + size_t(x / tile);
      auto slice = [&](double at) { return size_t(std::clamp(int(std::floor(at)), 0, slices - 1)); };
      points.push_back({view, slice(s) * tilesX * tilesY + column, column, slice(s - 2e-3) != slice(s + 2e-3)});
    }
  }
  return points;
}

// The box widened as the GPU widens occupancy boxes: by 1e-4 of its largest coordinate magnitude plus 1e-6.
Box padded(Box b) {
  const glm::dvec3 extent = glm::max(glm::abs(b.lo), glm::abs(b.hi));
  const double pad = 1e-4 * std::max({extent.x, extent.y, extent.z}) + 1e-6;
  b.lo -= pad;
  b.hi += pad;
  return b;
}

// How far the sphere misses the box (Arvo 1990); negative or zero where it touches it.
double sphereBoxGap(const glm::dvec3& c, double r, const Box& b) {
  const glm::dvec3 d = glm::max(b.lo - c, 0.0) + glm::max(c - b.hi, 0.0);
  return std::sqrt(glm::dot(d, d)) - r;
}

// A floor, boxes at several depths and a light set with every radius from 0 to 5 m.
Scene listScene() {
  Scene scene;
  scene.camera.position = {1.0f, 3.0f, 7.0f};
  scene.camera.target = {0.0f, 0.0f, -2.0f};
  scene.camera.nearPlane = 0.2f;
  scene.camera.farPlane = 50.0f;
  scene.addShape(Shape::Plane, glm::scale(glm::mat4(1.0f), glm::vec3(80.0f, 1.0f, 80.0f)), {});
  for (int i = 0; i < 6; ++i) {
    const glm::vec3 at(-6.0f + 2.5f * i, 1.0f, 2.0f - 5.0f * i);
    scene.addShape(Shape::Box, glm::scale(glm::translate(glm::mat4(1.0f), at), glm::vec3(1.0f, 2.0f, 1.0f)), {});
  }
  RandomLightSpec spec;
  spec.count = 2000;
  spec.seed = 21;
  spec.boundsMin = {-20.0f, -2.0f, -45.0f};
  spec.boundsMax = {20.0f, 8.0f, 12.0f};
  spec.radiusMin = 0.0f;
  spec.radiusMax = 5.0f;
  scene.lights = makeRandomLights(spec);
  return scene;
}

}  // namespace

TEST_CASE("clusters: GPU light lists hold every light reaching a cluster's surfaces and none missing its box") {
  PBR_REQUIRE_GL();
  const Scene scene = listScene();
  const int width = 320, height = 180;
  ClusterConfig config;
  config.tileSize = 32;
  config.slices = 16;
  const ShaderLibrary shaders;
  Renderer renderer(shaders, scene, width, height, RendererConfig{config});
  Profiler profiler(TimingMode::Serializing);
  renderer.renderFrame({}, profiler);
  renderer.renderFrame({}, profiler);
  const std::vector<std::vector<uint32_t>> lists = renderer.clusters().readLists();
  REQUIRE(renderer.lightStats().overflowedClusters == 0);

  const std::vector<SurfacePoint> points =
      surfacePoints(renderer, scene.camera, width, height, config.tileSize, config.slices);
  const size_t tiles = size_t((width + config.tileSize - 1) / config.tileSize) *
                       ((height + config.tileSize - 1) / config.tileSize);
  REQUIRE(lists.size() == tiles * config.slices);
  // Boxes of the points surely in each cluster, and of all points of each tile; clusters a borderline point may
  // join are not checked for tightness.
  std::vector<Box> clusterBoxes(lists.size()), tileBoxes(tiles);
  std::vector<bool> occupied(lists.size()), uncertain(lists.size());
  const size_t slicesApart = tiles;
  for (const SurfacePoint& p : points) {
    Box& t = tileBoxes[p.tile];
    t.lo = glm::min(t.lo, p.view);
    t.hi = glm::max(t.hi, p.view);
    occupied[p.cluster] = true;
    if (p.borderline) {
      for (size_t c : {p.cluster - std::min(p.cluster, slicesApart), p.cluster + slicesApart}) {
        if (c < lists.size()) uncertain[c] = true;
      }
      uncertain[p.cluster] = true;
      continue;
    }
    Box& b = clusterBoxes[p.cluster];
    b.lo = glm::min(b.lo, p.view);
    b.hi = glm::max(b.hi, p.view);
  }

  const glm::dmat4 view = glm::lookAtRH(glm::dvec3(scene.camera.position), glm::dvec3(scene.camera.target),
                                        glm::dvec3(scene.camera.up));
  std::vector<glm::dvec3> centers;
  for (const PointLight& l : scene.lights) centers.push_back(glm::dvec3(view * glm::dvec4(glm::dvec3(l.position), 1.0)));

  // Conservative: a light whose sphere reaches a surface point of a cluster (by more than 1e-5 of its distance,
  // float rounding) is in that cluster's list.
  std::vector<std::set<uint32_t>> reaching(lists.size());
  for (const SurfacePoint& p : points) {
    if (p.borderline) continue;
    for (size_t i = 0; i < centers.size(); ++i) {
      const double r = scene.lights[i].radius;
      if (r > 0.0 && glm::length(p.view - centers[i]) < r - 1e-5 * glm::length(centers[i])) {
        reaching[p.cluster].insert(static_cast<uint32_t>(i));
      }
    }
  }
  size_t missing = 0, extra = 0, listed = 0, reached = 0, active = 0, listedWithoutSurface = 0;
  for (size_t c = 0; c < lists.size(); ++c) {
    // Ascending in the light buffer's order, then as the scene's indices.
    CHECK(std::is_sorted(lists[c].begin(), lists[c].end()));
    CHECK(std::adjacent_find(lists[c].begin(), lists[c].end()) == lists[c].end());
    std::vector<uint32_t> list;
    for (uint32_t i : lists[c]) list.push_back(renderer.lights().sceneIndex(i));
    std::sort(list.begin(), list.end());
    listed += list.size();
    reached += reaching[c].size();
    for (uint32_t i : reaching[c]) missing += std::binary_search(list.begin(), list.end(), i) ? 0 : 1;
    if (!occupied[c] && !uncertain[c]) listedWithoutSurface += list.size();
    if (!occupied[c] || uncertain[c]) continue;
    ++active;
    // Tight: no light is listed whose sphere misses the padded box of the cluster's surfaces or of its tile's
    // (by more than 1e-5 of the box's size: float rounding).
    const Box box = padded(clusterBoxes[c]), tileBox = padded(tileBoxes[c % tiles]);
    const double tolerance = 1e-5 * std::max(glm::length(box.lo), glm::length(box.hi));
    for (uint32_t i : list) {
      const double r = scene.lights[i].radius;
      if (sphereBoxGap(centers[i], r, box) > tolerance || sphereBoxGap(centers[i], r, tileBox) > tolerance) ++extra;
    }
  }
  CAPTURE(active);
  CAPTURE(reached);
  CHECK(active > 20);
  CHECK(active < lists.size() / 2);  // most of the grid holds no surface
  CHECK(reached > 1000);
  CHECK(listed >= reached);
  CHECK(listedWithoutSurface == 0);
  CHECK(missing == 0);
  CHECK(extra == 0);
  CHECK(renderer.clusters().readStatus().activeClusters >= active);
}
