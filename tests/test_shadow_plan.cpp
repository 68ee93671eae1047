// The shadow planner (shadows/shadow_plan.hpp) and the atlas packing, on the CPU: squares never overlap and stay in
// the atlas, views without a receiver in view are skipped, a full atlas shrinks the least important lights first
// and counts every light it cannot shadow.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <vector>

#include "shadows/atlas_packing.hpp"
#include "shadows/shadow_plan.hpp"

namespace {

pbr::WorldBounds floorBounds() {
  pbr::WorldBounds b;
  b.add(glm::vec3(-10.0f, 0.0f, -10.0f));
  b.add(glm::vec3(10.0f, 2.0f, 10.0f));
  return b;
}

pbr::Camera camera() {
  pbr::Camera c;
  c.position = {0.0f, 5.0f, 8.0f};
  c.target = {0.0f, 0.0f, 0.0f};
  return c;
}

pbr::PointLight light(const glm::vec3& p, float radius) {
  pbr::PointLight l;
  l.position = p;
  l.radius = radius;
  l.castsShadows = true;
  return l;
}

std::vector<uint32_t> identity(size_t n) {
  std::vector<uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  return order;
}

// Every rendered view's square lies in the atlas and overlaps no other.
void checkSquares(const pbr::ShadowPlan& plan, int atlas) {
  std::vector<const pbr::ShadowViewPlan*> rendered;
  for (const pbr::ShadowViewPlan& v : plan.views) {
    if (v.size == 0) continue;
    CHECK(v.origin.x >= 0);
    CHECK(v.origin.y >= 0);
    CHECK(v.origin.x + v.size <= atlas);
    CHECK(v.origin.y + v.size <= atlas);
    rendered.push_back(&v);
  }
  for (size_t i = 0; i < rendered.size(); ++i) {
    for (size_t j = i + 1; j < rendered.size(); ++j) {
      const pbr::ShadowViewPlan &a = *rendered[i], &b = *rendered[j];
      const bool apart = a.origin.x + a.size <= b.origin.x || b.origin.x + b.size <= a.origin.x ||
                         a.origin.y + a.size <= b.origin.y || b.origin.y + b.size <= a.origin.y;
      CHECK(apart);
    }
  }
}

}  // namespace

TEST_CASE("shadow atlas: power-of-two squares that fit are packed without gaps or overlaps") {
  std::vector<pbr::AtlasSquare> squares;
  const std::vector<int> sizes = {64, 16, 256, 16, 128, 64, 32, 256, 16, 16, 128, 32, 256};
  for (size_t i = 0; i < sizes.size(); ++i) squares.push_back({sizes[i], i, {0, 0}});
  pbr::packSquares(squares);
  uint64_t area = 0;
  for (const pbr::AtlasSquare& s : squares) area += uint64_t(s.size) * s.size;
  REQUIRE(area <= 1024u * 1024u);
  for (size_t i = 0; i < squares.size(); ++i) {
    CHECK(squares[i].origin.x % squares[i].size == 0);
    CHECK(squares[i].origin.y % squares[i].size == 0);
    CHECK(squares[i].origin.x + squares[i].size <= 512);  // 4 x 256 and the rest fill the first 512 x 512 block
    for (size_t j = i + 1; j < squares.size(); ++j) {
      const pbr::AtlasSquare &a = squares[i], &b = squares[j];
      CHECK((a.origin.x + a.size <= b.origin.x || b.origin.x + b.size <= a.origin.x ||
             a.origin.y + a.size <= b.origin.y || b.origin.y + b.size <= a.origin.y));
    }
  }
}

TEST_CASE("shadow plan: a point light's cube faces, all skipped for a light behind the camera") {
  const std::vector<pbr::PointLight> lights = {light({0.0f, 1.0f, 0.0f}, 6.0f), light({0.0f, 1.0f, 60.0f}, 3.0f)};
  const std::vector<uint32_t> order = identity(lights.size());
  const std::vector<pbr::DirectionalLight> none;
  const pbr::Camera cam = camera();
  const pbr::ShadowPlan plan = pbr::planShadows({cam, 16.0f / 9.0f, 720, lights, order, none, floorBounds()});
  // The first light sits over the floor in view, each face's pyramid meeting the scene's bounds in view; the
  // second is behind the camera, beyond the floor: every face skipped.
  CHECK(plan.stats.shadowedLights == 2);
  CHECK(plan.views.size() == 12);
  CHECK((plan.lightViews[0] & pbr::kCubeShadow) != 0);
  CHECK((plan.lightViews[0] & ~pbr::kCubeShadow) == 1);
  for (int face = 0; face < 6; ++face) CHECK(plan.views[size_t(6 + face)].size == 0);
  CHECK(plan.stats.viewsRendered == 6);
  CHECK(plan.stats.viewsSkipped == 6);
  checkSquares(plan, 4096);
}

TEST_CASE("shadow plan: a full atlas halves the least important lights first and counts what it cannot shadow") {
  std::vector<pbr::PointLight> lights;
  for (int i = 0; i < 40; ++i) lights.push_back(light({-8.0f + 0.4f * float(i), 0.5f, 0.0f}, 1.0f + 0.1f * float(i)));
  const std::vector<uint32_t> order = identity(lights.size());
  const std::vector<pbr::DirectionalLight> none;
  const pbr::Camera cam = camera();
  pbr::ShadowInputs inputs{cam, 16.0f / 9.0f, 720, lights, order, none, floorBounds()};
  inputs.atlasSize = 16384;
  const pbr::ShadowPlan roomy = pbr::planShadows(inputs);
  CHECK(roomy.stats.shrunkLights == 0);
  CHECK(roomy.stats.unshadowedLights == 0);
  inputs.atlasSize = 256;
  const pbr::ShadowPlan tight = pbr::planShadows(inputs);
  CHECK(tight.stats.shrunkLights > 0);
  CHECK(tight.stats.shadowedLights + tight.stats.unshadowedLights == 40);
  checkSquares(tight, 256);
  // At the least size 16 of them fit; the rest are counted, not dropped silently.
  inputs.atlasSize = 64;
  const pbr::ShadowPlan full = pbr::planShadows(inputs);
  CHECK(full.stats.unshadowedLights > 0);
  CHECK(full.stats.shadowedLights + full.stats.unshadowedLights == 40);
  CHECK(std::count(full.lightViews.begin(), full.lightViews.end(), 0u) == long(full.stats.unshadowedLights));
  checkSquares(full, 64);
}

TEST_CASE("shadow plan: a sun gets texel-snapped cascades over the scene's depth range in view") {
  const std::vector<pbr::PointLight> lights;
  const std::vector<uint32_t> order;
  const std::vector<pbr::DirectionalLight> suns = {
      {glm::normalize(glm::vec3(-0.3f, -1.0f, 0.2f)), glm::vec3(1.0f), 1.0f}};
  pbr::Camera cam = camera();
  const pbr::ShadowPlan a = pbr::planShadows({cam, 16.0f / 9.0f, 720, lights, order, suns, floorBounds()});
  REQUIRE(a.views.size() == size_t(pbr::kCascades));
  CHECK(a.header.directional[0].x == 1);
  CHECK(a.header.directional[0].y == unsigned(pbr::kCascades));
  for (int c = 1; c < pbr::kCascades; ++c) CHECK(a.header.cascadeEnds[c] > a.header.cascadeEnds[c - 1]);
  // Moving the camera by a fraction of a texel sideways moves no cascade's texel grid: the projections differ by
  // whole texels in light space (the translation column, in texels, stays an integer apart).
  cam.position.x += 1e-3f;
  cam.target.x += 1e-3f;
  const pbr::ShadowPlan b = pbr::planShadows({cam, 16.0f / 9.0f, 720, lights, order, suns, floorBounds()});
  for (int c = 0; c < pbr::kCascades; ++c) {
    const pbr::ShadowViewPlan &va = a.views[size_t(c)], &vb = b.views[size_t(c)];
    for (int axis = 0; axis < 2; ++axis) {
      const double shift = (double(va.viewProjection[3][axis]) - double(vb.viewProjection[3][axis])) * va.size / 2.0;
      CHECK(std::abs(shift - std::round(shift)) < 1e-2);
    }
  }
}
