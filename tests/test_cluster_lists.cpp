#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "renderer/renderer.hpp"
#include "core/builtin_scenes.hpp"
#include "tests/gl_test_context.hpp"

using namespace pbr;

namespace {

struct Box {
  glm::dvec3 lo, hi;
  std::array<glm::dvec3, 4> planes;  // unit inward normals of the tile column's side planes, through the eye
  double planePad;
};

// The froxel bounds as the clustering contract states them, in double precision: screen tiles of `tile` pixels
// x exponential slices z_k = near (far/near)^(k/S), the view-space AABB of the 8 corners, widened by 1e-4 of
// its largest coordinate magnitude plus 1e-6; and the tile's four side planes, widened by 1e-4 of the distance to
// the column's farthest corner on the far plane plus 1e-6.
std::vector<Box> cpuClusterBounds(const Camera& cam, int width, int height, int tile, int slices) {
  const int tilesX = (width + tile - 1) / tile, tilesY = (height + tile - 1) / tile;
  const double tanHalf = std::tan(glm::radians(double(cam.fovYDeg)) / 2.0);
  const double aspect = double(width) / height;
  std::vector<Box> boxes;
  for (int k = 0; k < slices; ++k) {
    const double zNear = cam.nearPlane * std::pow(double(cam.farPlane) / cam.nearPlane, double(k) / slices);
    const double zFar = cam.nearPlane * std::pow(double(cam.farPlane) / cam.nearPlane, double(k + 1) / slices);
    for (int ty = 0; ty < tilesY; ++ty) {
      for (int tx = 0; tx < tilesX; ++tx) {
        const double x0 = double(tx * tile) / width * 2 - 1, x1 = double(std::min((tx + 1) * tile, width)) / width * 2 - 1;
        const double y0 = double(ty * tile) / height * 2 - 1, y1 = double(std::min((ty + 1) * tile, height)) / height * 2 - 1;
        Box b{glm::dvec3(1e300), glm::dvec3(-1e300), {}, 0.0};
        const double sx = aspect * tanHalf, sy = tanHalf;
        b.planes = {glm::normalize(glm::dvec3(1, 0, x0 * sx)), glm::normalize(glm::dvec3(-1, 0, -x1 * sx)),
                    glm::normalize(glm::dvec3(0, 1, y0 * sy)), glm::normalize(glm::dvec3(0, -1, -y1 * sy))};
        const glm::dvec3 farCorner(std::max(std::abs(x0), std::abs(x1)) * sx, std::max(std::abs(y0), std::abs(y1)) * sy, 1);
        b.planePad = 1e-4 * cam.farPlane * glm::length(farCorner) + 1e-6;
        for (double nx : {x0, x1}) {
          for (double ny : {y0, y1}) {
            for (double z : {zNear, zFar}) {
              const glm::dvec3 p(nx * aspect * tanHalf * z, ny * tanHalf * z, -z);
              b.lo = glm::min(b.lo, p);
              b.hi = glm::max(b.hi, p);
            }
          }
        }
        const glm::dvec3 extent = glm::max(glm::abs(b.lo), glm::abs(b.hi));
        const double pad = 1e-4 * std::max({extent.x, extent.y, extent.z}) + 1e-6;
        b.lo -= pad;
        b.hi += pad;
        boxes.push_back(b);
      }
    }
  }
  return boxes;
}

// How far the sphere misses the cluster: its gap to the box, or to the farthest-off padded side plane; negative
// or zero means the light is listed.
double sphereClusterGap(const glm::dvec3& c, double r, const Box& b) {
  const glm::dvec3 d = glm::max(b.lo - c, 0.0) + glm::max(c - b.hi, 0.0);
  double gap = std::sqrt(glm::dot(d, d)) - r;
  for (const glm::dvec3& n : b.planes) gap = std::max(gap, -glm::dot(n, c) - b.planePad - r);
  return gap;
}

}  // namespace

TEST_CASE("clusters: GPU light lists equal a CPU froxel/sphere test for a fixed camera") {
  PBR_REQUIRE_GL();
  Scene scene;
  scene.camera.position = {1.0f, 3.0f, 7.0f};
  scene.camera.target = {0.0f, 0.0f, -2.0f};
  scene.camera.nearPlane = 0.2f;
  scene.camera.farPlane = 50.0f;
  scene.addShape(Shape::Plane, glm::scale(glm::mat4(1.0f), glm::vec3(80.0f, 1.0f, 80.0f)), {});
  RandomLightSpec spec;
  spec.count = 2000;
  spec.seed = 21;
  spec.boundsMin = {-20.0f, -2.0f, -45.0f};
  spec.boundsMax = {20.0f, 8.0f, 12.0f};
  spec.radiusMin = 0.0f;
  spec.radiusMax = 5.0f;
  scene.lights = makeRandomLights(spec);

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

  const std::vector<Box> boxes = cpuClusterBounds(scene.camera, width, height, config.tileSize, config.slices);
  REQUIRE(lists.size() == boxes.size());
  const glm::dmat4 view = glm::lookAtRH(glm::dvec3(scene.camera.position), glm::dvec3(scene.camera.target),
                                        glm::dvec3(scene.camera.up));
  std::vector<glm::dvec3> centers;
  for (const PointLight& l : scene.lights) centers.push_back(glm::dvec3(view * glm::dvec4(glm::dvec3(l.position), 1.0)));

  size_t missing = 0, extra = 0, listed = 0, borderline = 0;
  for (size_t c = 0; c < boxes.size(); ++c) {
    const std::vector<uint32_t>& list = lists[c];
    CHECK(std::is_sorted(list.begin(), list.end()));
    CHECK(std::adjacent_find(list.begin(), list.end()) == list.end());
    listed += list.size();
    const double scale = std::max(glm::length(boxes[c].lo), glm::length(boxes[c].hi));
    for (size_t i = 0; i < scene.lights.size(); ++i) {
      const double gap = sphereClusterGap(centers[i], scene.lights[i].radius, boxes[c]);
      const bool inList = std::binary_search(list.begin(), list.end(), static_cast<uint32_t>(i));
      // Float rounding on the GPU may decide spheres that touch a box within 1e-5 of its size either way, and
      // a side plane within 1e-5 of the light's distance.
      if (std::abs(gap) < 1e-5 * std::max(scale, glm::length(centers[i]))) {
        ++borderline;
        continue;
      }
      if (gap <= 0.0 && !inList) ++missing;
      if (gap > 0.0 && inList) ++extra;
    }
  }
  CAPTURE(borderline);
  CHECK(listed > 1000);
  CHECK(missing == 0);
  CHECK(extra == 0);
}
