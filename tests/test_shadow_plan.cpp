// The shadow planner (shadows/shadow_plan.hpp) and the atlas packing, on the CPU: squares never overlap and stay in
// the atlas, views without a receiver in view are skipped, a full atlas shrinks the least important lights first
// and counts every light it cannot shadow, planar casters (core/scene/caster_plane.hpp) are found and left out of
// the views of lights they hide nothing visible from, and the texel rectangles a caster covers in a view.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <optional>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include "core/scene/caster_plane.hpp"
#include "core/scene/mesh.hpp"
#include "shadows/atlas_packing.hpp"
#include "shadows/shadow_plan.hpp"
#include "shadows/shadow_views.hpp"

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

// A box of receivers as the cluster occupancy would report it through `cam`: one view-space box, around the
// box's corners seen from the camera.
pbr::ShadowReceivers receiversIn(const pbr::Camera& cam, const pbr::WorldBounds& world) {
  const glm::mat4 view = cam.view();
  pbr::ViewSpaceBox box{glm::vec3(1e30f), glm::vec3(-1e30f), 0};
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 corner(i & 1 ? world.max.x : world.min.x, i & 2 ? world.max.y : world.min.y,
                           i & 4 ? world.max.z : world.min.z);
    const glm::vec3 p(view * glm::vec4(corner, 1.0f));
    box.min = glm::min(box.min, p);
    box.max = glm::max(box.max, p);
  }
  return pbr::ShadowReceivers({box}, glm::inverse(view));
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
  const pbr::ShadowReceivers floor = receiversIn(cam, floorBounds());
  const pbr::ShadowPlan plan = pbr::planShadows({cam, 16.0f / 9.0f, 720, lights, order, none, floorBounds(), floor});
  // The first light sits over the floor, each face's pyramid meeting the receivers; the second is behind the
  // camera, beyond the floor: every face skipped.
  CHECK(plan.stats.shadowedLights == 2);
  CHECK(plan.views.size() == 12);
  CHECK((plan.lightViews[0] & pbr::kCubeShadow) != 0);
  // First view + 1 in bits 0-25, log2 of the faces' side in bits 26-29.
  CHECK((plan.lightViews[0] & 0x3ffffffu) == 1);
  CHECK((1 << ((plan.lightViews[0] >> 26) & 15u)) == plan.views[0].size);
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
  const pbr::ShadowReceivers floor = receiversIn(cam, floorBounds());
  pbr::ShadowInputs inputs{cam, 16.0f / 9.0f, 720, lights, order, none, floorBounds(), floor};
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

TEST_CASE("shadow plan: a sun gets texel-snapped cascades over the receivers' depth range in view") {
  const std::vector<pbr::PointLight> lights;
  const std::vector<uint32_t> order;
  const std::vector<pbr::DirectionalLight> suns = {
      {glm::normalize(glm::vec3(-0.3f, -1.0f, 0.2f)), glm::vec3(1.0f), 1.0f}};
  pbr::Camera cam = camera();
  const pbr::ShadowReceivers floorA = receiversIn(cam, floorBounds());
  const pbr::ShadowPlan a = pbr::planShadows({cam, 16.0f / 9.0f, 720, lights, order, suns, floorBounds(), floorA});
  REQUIRE(a.views.size() == size_t(pbr::kCascades));
  CHECK(a.header.directional[0].x == 1);
  CHECK(a.header.directional[0].y == unsigned(pbr::kCascades));
  for (int c = 1; c < pbr::kCascades; ++c) CHECK(a.header.cascadeEnds[c] > a.header.cascadeEnds[c - 1]);
  // Moving the camera by a fraction of a texel sideways moves no cascade's texel grid: the projections differ by
  // whole texels in light space (the translation column, in texels, stays an integer apart).
  cam.position.x += 1e-3f;
  cam.target.x += 1e-3f;
  const pbr::ShadowReceivers floorB = receiversIn(cam, floorBounds());
  const pbr::ShadowPlan b = pbr::planShadows({cam, 16.0f / 9.0f, 720, lights, order, suns, floorBounds(), floorB});
  for (int c = 0; c < pbr::kCascades; ++c) {
    const pbr::ShadowViewPlan &va = a.views[size_t(c)], &vb = b.views[size_t(c)];
    for (int axis = 0; axis < 2; ++axis) {
      const double shift = (double(va.viewProjection[3][axis]) - double(vb.viewProjection[3][axis])) * va.size / 2.0;
      CHECK(std::abs(shift - std::round(shift)) < 1e-2);
    }
  }
}

TEST_CASE("shadow views: receivers at one depth get cascades, receivers out of the depth range none") {
  // A floor seen head-on lies at one view depth; casters out of view still shadow it, so its cascades must exist,
  // ascending and ending past it.
  const pbr::Camera cam = camera();
  const pbr::CascadeSplits flat = pbr::cascadeSplits(cam, 6.0f, 6.0f, pbr::kCascades);
  REQUIRE(flat.count == pbr::kCascades);
  CHECK(flat.begin == 6.0f);
  float previous = flat.begin;
  for (const float end : flat.ends) {
    CHECK(end > previous);
    previous = end;
  }
  CHECK(flat.ends.back() == doctest::Approx(6.006f).epsilon(1e-6));
  CHECK(pbr::cascadeSplits(cam, cam.farPlane * 2.0f, cam.farPlane * 3.0f, pbr::kCascades).count == 0);
}

TEST_CASE("shadow views: each cascade's square holds its slice of the view, perspective or orthographic") {
  const glm::vec3 sun = glm::normalize(glm::vec3(-0.3f, -1.0f, 0.2f));
  const float aspect = 16.0f / 9.0f;
  for (const bool orthographic : {false, true}) {
    CAPTURE(orthographic);
    pbr::Camera cam = camera();
    cam.orthographic = orthographic;
    cam.orthoHalfHeight = 3.0f;
    const pbr::CascadeSplits splits = pbr::cascadeSplits(cam, 2.0f, 20.0f, pbr::kCascades);
    REQUIRE(splits.count == pbr::kCascades);
    const glm::vec3 forward = glm::normalize(cam.target - cam.position);
    const glm::vec3 right = glm::normalize(glm::cross(forward, cam.up)), up = glm::cross(right, forward);
    for (int c = 0; c < splits.count; ++c) {
      CAPTURE(c);
      const pbr::ShadowViewPlan v = pbr::cascadeView(cam, aspect, splits, c, sun, floorBounds(), 1024);
      const float begin = c == 0 ? splits.begin : splits.ends[size_t(c - 1)], end = splits.ends[size_t(c)];
      for (int i = 0; i < 8; ++i) {
        // The slice's corners: half a view of 2 ortho half-heights at every depth, or 2 z tan(fov / 2) at depth z.
        const float z = i & 4 ? end : begin;
        const float halfY = orthographic ? cam.orthoHalfHeight : z * std::tan(glm::radians(cam.fovYDeg) / 2.0f);
        const glm::vec3 corner = cam.position + forward * z + right * (halfY * aspect * (i & 1 ? 1.0f : -1.0f)) +
                                 up * (halfY * (i & 2 ? 1.0f : -1.0f));
        const glm::vec4 clip = v.viewProjection * glm::vec4(corner, 1.0f);
        CHECK(std::abs(clip.x / clip.w) <= 1.0f + 1e-5f);
        CHECK(std::abs(clip.y / clip.w) <= 1.0f + 1e-5f);
      }
    }
  }
}

TEST_CASE("shadow views: the cube faces' frames are those shadow_sample.glsl's cubeFaceLocal assumes") {
  // cubeFaceLocal reads a face's (right, up, axis) coordinates as these signed components of d; the views are
  // rendered with frameAround's frames, so the two must be the same vectors.
  const glm::vec3 X(1, 0, 0), Y(0, 1, 0), Z(0, 0, 1);
  const glm::vec3 axes[6] = {X, -X, Y, -Y, Z, -Z};
  const glm::vec3 rights[6] = {Z, -Z, -Z, Z, -X, X};
  const glm::vec3 ups[6] = {Y, Y, X, X, Y, Y};
  for (int face = 0; face < 6; ++face) {
    glm::vec3 right, up;
    pbr::frameAround(axes[face], right, up);
    CHECK(glm::all(glm::equal(right, rights[face])));
    CHECK(glm::all(glm::equal(up, ups[face])));
  }
}

TEST_CASE("shadow maps: a light's entry and a view's square pack what the shader unpacks") {
  const uint32_t entry = pbr::lightShadowEntry(41, 256, pbr::LightShadowKind::Cube);
  CHECK((entry & 0x3ffffffu) == 42);
  CHECK(((entry >> 26) & 15u) == 8);
  CHECK((entry & pbr::kCubeShadow) != 0);
  CHECK((entry & pbr::kShadowFrameX) == 0);
  const uint32_t spot = pbr::lightShadowEntry(0, 16, pbr::LightShadowKind::SpotFrameX);
  CHECK((spot & pbr::kCubeShadow) == 0);
  CHECK((spot & pbr::kShadowFrameX) != 0);
  CHECK((spot & 0x3ffffffu) == 1);
  CHECK((pbr::lightShadowEntry(0, 16, pbr::LightShadowKind::Spot) & (pbr::kCubeShadow | pbr::kShadowFrameX)) == 0);
  const uint32_t square = pbr::packShadowSquare({16320, 1024}, 64);
  CHECK((square & 0x3fffu) == 16320);
  CHECK(((square >> 14) & 0x3fffu) == 1024);
  CHECK((square >> 28) == 6);
  CHECK(pbr::packShadowSquare({0, 0}, 0) == 0);
  CHECK(pbr::packShadowSquare({0, 0}, 16) != 0);
}

TEST_CASE("shadow plan: with the clusters' receivers, only views that hold an occupied cluster are rendered") {
  // The camera at the origin looking down -z, so that view space is world space.
  pbr::Camera cam;
  cam.position = {0.0f, 0.0f, 0.0f};
  cam.target = {0.0f, 0.0f, -1.0f};
  cam.nearPlane = 0.1f;
  cam.farPlane = 100.0f;
  const glm::mat4 inverseView(1.0f);
  pbr::WorldBounds scene;
  scene.add(glm::vec3(-20.0f, -20.0f, -40.0f));
  scene.add(glm::vec3(20.0f, 20.0f, 0.0f));
  const std::vector<uint32_t> order = identity(1);
  const std::vector<pbr::PointLight> none;
  const std::vector<pbr::DirectionalLight> noSuns;

  SUBCASE("a point light over the one occupied cluster renders the face looking down, and no other") {
    const pbr::ShadowReceivers receivers({{{-0.5f, -0.5f, -5.5f}, {0.5f, 0.5f, -4.5f}, 0}}, inverseView);
    const std::vector<pbr::PointLight> lights = {light({0.0f, 3.0f, -5.0f}, 6.0f)};
    const pbr::ShadowPlan plan = pbr::planShadows({cam, 16.0f / 9.0f, 720, lights, order, noSuns, scene, receivers});
    REQUIRE(plan.views.size() == 6);
    CHECK(plan.stats.viewsRendered == 1);
    CHECK(plan.stats.viewsSkipped == 5);
    CHECK(plan.views[3].size > 0);  // -Y
    // The scene's bounds, all about the light, meet every face: the receivers, not the casters, decide.
    const pbr::ShadowPlan everywhere =
        pbr::planShadows({cam, 16.0f / 9.0f, 720, lights, order, noSuns, scene, receiversIn(cam, scene)});
    CHECK(everywhere.stats.viewsRendered == 6);
  }

  SUBCASE("a sun's cascades span the receivers' depths, and a cascade over none of them is not rendered") {
    // Receivers near depth 2 and depth 30: the practical split (lambda 0.75) over [1.5, 30.5] ends near 4.6, 9.1,
    // 16.6 and 30.5, so the middle two cascades hold no receiver.
    const pbr::ShadowReceivers receivers(
        {{{-0.5f, -0.5f, -2.5f}, {0.5f, 0.5f, -1.5f}, 0}, {{-0.5f, -0.5f, -30.5f}, {0.5f, 0.5f, -29.5f}, 1}},
        inverseView);
    CHECK(receivers.nearDepth() == doctest::Approx(1.5f));
    CHECK(receivers.farDepth() == doctest::Approx(30.5f));
    pbr::DirectionalLight sun;
    sun.direction = glm::normalize(glm::vec3(0.2f, -1.0f, 0.1f));
    const std::vector<pbr::DirectionalLight> suns = {sun};
    const std::vector<uint32_t> noOrder;
    const pbr::ShadowPlan plan = pbr::planShadows({cam, 16.0f / 9.0f, 720, none, noOrder, suns, scene, receivers});
    REQUIRE(plan.views.size() == size_t(pbr::kCascades));
    CHECK(plan.header.cascadeEnds[3] == doctest::Approx(30.5f));
    CHECK(plan.views[0].size > 0);
    CHECK(plan.views[1].size == 0);
    CHECK(plan.views[2].size == 0);
    CHECK(plan.views[3].size > 0);
    CHECK(plan.stats.viewsSkipped == 2);
    // The texel sizes of the two rendered cascades, as the stats report them.
    CHECK(plan.stats.cascadeTexelMin == doctest::Approx(std::min(plan.views[0].texelWorld, plan.views[3].texelWorld)));
    CHECK(plan.stats.cascadeTexelMax == doctest::Approx(std::max(plan.views[0].texelWorld, plan.views[3].texelWorld)));
  }
}

TEST_CASE("shadow receivers: meetsViews finds, in one pass, the views meets finds one by one") {
  // Clusters in 24 tiles over a slab of view space, and lights around and inside them with their six cube faces.
  std::vector<pbr::ViewSpaceBox> boxes;
  uint32_t seed = 12345u;
  const auto next = [&seed] {
    seed = seed * 1664525u + 1013904223u;
    return float(seed >> 8) / float(1u << 24);
  };
  for (uint32_t tile = 0; tile < 24; ++tile) {
    for (int c = 0; c < 6; ++c) {
      const glm::vec3 lo(-12.0f + 24.0f * next(), -3.0f + 6.0f * next(), -30.0f + 28.0f * next());
      boxes.push_back({lo, lo + glm::vec3(0.2f + next(), 0.2f + next(), 0.2f + next()), tile});
    }
  }
  const pbr::ShadowReceivers receivers(boxes, glm::mat4(1.0f));
  const glm::vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  size_t met = 0, missed = 0;
  for (int l = 0; l < 200; ++l) {
    const glm::vec4 sphere(-14.0f + 28.0f * next(), -4.0f + 8.0f * next(), -32.0f + 32.0f * next(),
                           0.5f + 6.0f * next());
    std::vector<pbr::FrustumPlanes> faces;
    for (const glm::vec3& axis : axes) {
      faces.push_back(pbr::frustumPlanes(
          pbr::perspectiveView(glm::vec3(sphere), axis, 1.0f, sphere.w, pbr::kMinShadowView, pbr::kShadowBorderTexels)
              .viewProjection));
    }
    const uint32_t bits = receivers.meetsViews(sphere, faces);
    for (size_t f = 0; f < faces.size(); ++f) {
      const bool one = receivers.meets(sphere, faces[f]);
      CHECK(((bits >> f & 1u) != 0u) == one);
      (one ? met : missed) += 1;
    }
  }
  // Both outcomes occur often enough to be tested.
  CHECK(met > 100);
  CHECK(missed > 100);
}

TEST_CASE("caster planes: a flat mesh under any pose has its plane, a mesh with a vertex off it has none") {
  const pbr::MeshData plane = pbr::makePlaneMesh();  // y = 0, normal +Y
  // Tilted by 30 degrees about z, scaled unevenly and moved: the plane's normal and offset follow the pose.
  const glm::mat4 pose = glm::scale(glm::rotate(glm::translate(glm::mat4(1.0f), {2.0f, 1.0f, -3.0f}),
                                                glm::radians(30.0f), glm::vec3(0.0f, 0.0f, 1.0f)),
                                    glm::vec3(8.0f, 1.0f, 5.0f));
  const std::optional<pbr::CasterPlane> found = pbr::casterPlane(plane, pose);
  REQUIRE(found.has_value());
  const glm::vec3 normal(-std::sin(glm::radians(30.0f)), std::cos(glm::radians(30.0f)), 0.0f);
  // The normal is the plane's up to its sign; either sign names the same sides, swapped.
  const float sign = glm::dot(glm::vec3(found->plane), normal) > 0.0f ? 1.0f : -1.0f;
  CHECK(glm::length(glm::vec3(found->plane) - sign * normal) < 1e-5f);
  // The pose's origin lies on the plane; a point a unit along the normal from it, a unit from it.
  CHECK(std::abs(glm::dot(glm::vec3(found->plane), glm::vec3(2.0f, 1.0f, -3.0f)) + found->plane.w) < 1e-5f);
  CHECK(std::abs(glm::dot(glm::vec3(found->plane), glm::vec3(2.0f, 1.0f, -3.0f) + normal) + found->plane.w) ==
        doctest::Approx(1.0f).epsilon(1e-5));
  CHECK(found->thickness < 1e-4f);

  CHECK_FALSE(pbr::casterPlane(pbr::makeBoxMesh(), glm::mat4(1.0f)).has_value());
  CHECK_FALSE(pbr::casterPlane(pbr::makeSphereMesh(16, 8), glm::mat4(1.0f)).has_value());
  pbr::MeshData bent = plane;
  bent.vertices[0].position.y += 1e-3f;  // a millimetre off a metre-wide square
  CHECK_FALSE(pbr::casterPlane(bent, glm::mat4(1.0f)).has_value());
  pbr::MeshData line = plane;
  for (pbr::Vertex& v : line.vertices) v.position.z = 0.0f;  // every triangle without area
  CHECK_FALSE(pbr::casterPlane(line, glm::mat4(1.0f)).has_value());
}

TEST_CASE("caster planes: a plane may hide a visible point only on its side away from the light") {
  const pbr::CasterPlane floor{glm::vec4(0.0f, 1.0f, 0.0f, 0.0f), 1e-6f};  // y = 0
  const uint32_t above = 1u, below = 2u, both = 3u;
  const glm::vec4 lampAbove(0.0f, 3.0f, 0.0f, 1.0f), lampBelow(0.0f, -3.0f, 0.0f, 1.0f);
  const glm::vec4 sunFromAbove(0.3f, -1.0f, 0.0f, 0.0f), sunFromBelow(0.3f, 1.0f, 0.0f, 0.0f);
  CHECK_FALSE(pbr::planeMayShadow(floor, above, 0, lampAbove));
  CHECK_FALSE(pbr::planeMayShadow(floor, 0u, 0, lampAbove));  // nothing but the plane's own points in view
  CHECK(pbr::planeMayShadow(floor, below, 0, lampAbove));
  CHECK(pbr::planeMayShadow(floor, both, 0, lampAbove));
  CHECK(pbr::planeMayShadow(floor, above, 0, lampBelow));
  CHECK_FALSE(pbr::planeMayShadow(floor, below, 0, lampBelow));
  CHECK_FALSE(pbr::planeMayShadow(floor, above, 0, sunFromAbove));
  CHECK(pbr::planeMayShadow(floor, below, 0, sunFromAbove));
  CHECK(pbr::planeMayShadow(floor, above, 0, sunFromBelow));
  // A lamp on the plane and a sun along it: kept, whatever the sides.
  CHECK(pbr::planeMayShadow(floor, 0u, 0, glm::vec4(1.0f, 0.0f, 0.0f, 1.0f)));
  CHECK(pbr::planeMayShadow(floor, 0u, 0, glm::vec4(1.0f, 0.0f, 0.0f, 0.0f)));
  // Plane 1's sides are bits 2 and 3.
  CHECK_FALSE(pbr::planeMayShadow(floor, below, 1, lampAbove));
  CHECK(pbr::planeMayShadow(floor, below << 2, 1, lampAbove));
}

TEST_CASE("shadow plan: a light's views leave out the planes that hide nothing visible from it") {
  // A lamp above the floor and one below it, a sun from above; planes: the floor (y = 0) and a wall (x = 4) with
  // visible points on the lamps' side of both and beyond the floor only.
  const std::vector<pbr::PointLight> lights = {light({0.0f, 1.0f, 0.0f}, 6.0f), light({1.0f, -1.0f, 0.0f}, 6.0f)};
  const std::vector<uint32_t> order = identity(lights.size());
  const std::vector<pbr::DirectionalLight> suns = {{glm::normalize(glm::vec3(0.2f, -1.0f, 0.1f)), glm::vec3(1.0f),
                                                    1.0f}};
  const pbr::Camera cam = camera();
  const pbr::ShadowReceivers floor = receiversIn(cam, floorBounds());
  pbr::ShadowInputs inputs{cam, 16.0f / 9.0f, 720, lights, order, suns, floorBounds(), floor};
  inputs.casterPlanes = {{glm::vec4(0.0f, 1.0f, 0.0f, 0.0f), 1e-6f}, {glm::vec4(1.0f, 0.0f, 0.0f, -4.0f), 1e-6f}};
  inputs.planeSides = 0x1u | 0x2u | 0x8u;  // the floor: points above and below; the wall: points on x < 4 only
  const pbr::ShadowPlan plan = pbr::planShadows(inputs);
  uint32_t leftOut = 0;
  for (const pbr::ShadowViewPlan& v : plan.views) {
    if (v.size == 0) continue;
    // The floor hides points from every light here; the wall from none of them (all lie on x < 4, with the points).
    CHECK(v.skipPlanes == 0x2u);
    leftOut += 1;
  }
  CHECK(plan.stats.planesLeftOut == leftOut);
  inputs.planeSides = 0x1u | 0x8u;  // nothing visible below the floor: the lamp under it keeps it, the others not
  const pbr::ShadowPlan above = pbr::planShadows(inputs);
  for (const pbr::ShadowViewPlan& v : above.views) {
    if (v.size == 0) continue;
    const bool lampBelow = v.reach.w > 0.0f && v.reach.y < 0.0f;
    CHECK(v.skipPlanes == (lampBelow ? 0x2u : 0x3u));
  }
}

TEST_CASE("caster rectangles: a box's texels in a view, a texel wider, whole behind the eye, none outside") {
  // An orthographic view of x, y in [-4, 4] onto a 64-texel square at (128, 256): 8 texels a unit.
  const glm::mat4 ortho = glm::ortho(-4.0f, 4.0f, -4.0f, 4.0f, -10.0f, 10.0f);
  const glm::ivec4 viewport(128, 256, 64, 64);
  pbr::WorldBounds box;
  box.add({-1.0f, 0.5f, 0.0f});
  box.add({1.25f, 2.0f, 1.0f});
  // x: (-1 + 4) * 8 = 24 to (1.25 + 4) * 8 = 42; y: 36 to 48; one texel more each way.
  CHECK(pbr::coveredRect(box, ortho, viewport) == glm::ivec4(128 + 23, 256 + 35, 20, 14));
  pbr::WorldBounds across;
  across.add({-9.0f, -9.0f, 0.0f});
  across.add({0.0f, 0.0f, 0.0f});
  CHECK(pbr::coveredRect(across, ortho, viewport) == glm::ivec4(128, 256, 33, 33));  // clipped to the viewport
  pbr::WorldBounds outside;
  outside.add({5.0f, 5.0f, 0.0f});
  outside.add({6.0f, 6.0f, 0.0f});
  CHECK(pbr::emptyRect(pbr::coveredRect(outside, ortho, viewport)));
  // A perspective view (a shadow view from the origin down -z, 90 degrees, its near plane at 1e-3 of a radius of
  // 100, reversed Z) and boxes reaching behind its eye: what lies in front of the near plane.
  const glm::mat4 perspective =
      pbr::perspectiveView(glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, -1.0f), 1.0f, 100.0f, 64, 0).viewProjection;
  pbr::WorldBounds straddling;  // reaching the eye: its projection grows without bound there
  straddling.add({-1.0f, -1.0f, -5.0f});
  straddling.add({1.0f, 1.0f, 2.0f});
  CHECK(pbr::coveredRect(straddling, perspective, viewport) == viewport);
  pbr::WorldBounds aside;  // beside the eye, reaching behind it: in front, x / -z runs from 2 / 8 past the edge
  aside.add({2.0f, -0.5f, -8.0f});
  aside.add({3.0f, 0.5f, 4.0f});
  // NDC x from 0.25: texel 128 + 40 less one, to the viewport's right edge; y past both edges.
  CHECK(pbr::coveredRect(aside, perspective, viewport) == glm::ivec4(128 + 39, 256, 64 - 39, 64));
  pbr::WorldBounds behindEye;  // wholly behind the eye: nothing drawn
  behindEye.add({-1.0f, -1.0f, 1.0f});
  behindEye.add({1.0f, 1.0f, 3.0f});
  CHECK(pbr::emptyRect(pbr::coveredRect(behindEye, perspective, viewport)));
  // Joining and intersecting; an empty rectangle joins as nothing.
  const glm::ivec4 a(0, 0, 10, 10), b(5, 8, 10, 4), none(3, 3, 0, 0);
  CHECK(pbr::joinRects(a, b) == glm::ivec4(0, 0, 15, 12));
  CHECK(pbr::joinRects(none, b) == b);
  CHECK(pbr::intersectRects(a, b) == glm::ivec4(5, 8, 5, 2));
  CHECK(pbr::emptyRect(pbr::intersectRects(a, glm::ivec4(10, 0, 4, 4))));
}
