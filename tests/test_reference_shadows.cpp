// The reference's shadow rays against shadows computed here from the geometry alone: a sphere's under a point light
// (the cone tangent to the sphere), under a directional light (the cylinder around it) and within a spot light's
// cone, a square card's from either face, and which lights cast under each ShadowMode.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <utility>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "core/scene/scene.hpp"
#include "reference/raycast.hpp"
#include "reference/reference_renderer.hpp"

using namespace pbr;
using namespace pbr::reference;

namespace {

constexpr int kWidth = 160, kHeight = 120;
// The sphere (radius r, centre h above the floor) and the point light straight above it (H above the floor).
constexpr double kRadius = 1.0, kSphereHeight = 2.0, kLightHeight = 6.0;
// Floor points this close to a shadow's edge are not judged: a tessellated sphere's outline differs from the exact
// one by about r (1 - cos(pi / 64)) = 0.0012 r, which the cone from the light widens about 1.7-fold; the band is
// some 15 times that, and far wider than the shadow rays' offset (1e-6 of the scene).
constexpr double kBand = 0.03 * kRadius;

glm::mat4 placed(const glm::vec3& at, const glm::vec3& scale) {
  return glm::scale(glm::translate(glm::mat4(1.0f), at), scale);
}

// Turned over, half a turn about x: a plane's front face then faces down.
glm::mat4 turnedOver(const glm::mat4& m) { return glm::rotate(m, float(kPi), glm::vec3(1.0f, 0.0f, 0.0f)); }

// A 16 x 16 grey floor (object 0) seen from above at an angle, no ambient light: where no light reaches, black.
Scene floorScene() {
  Scene s;
  s.name = "shadows";
  s.camera.position = {0.0f, 7.0f, 6.0f};
  s.camera.target = {0.0f, 0.0f, 0.0f};
  s.camera.fovYDeg = 45.0f;
  s.camera.nearPlane = 0.5f;
  s.camera.farPlane = 40.0f;
  s.addShape(Shape::Plane, placed({0, 0, 0}, {16.0f, 1.0f, 16.0f}), Material{glm::vec3(0.5f), 0.7f, 0.0f});
  return s;
}

void addSphere(Scene& s) {
  s.addShape(Shape::Sphere, placed({0.0f, float(kSphereHeight), 0.0f}, glm::vec3(float(2.0 * kRadius))),
             Material{{0.8f, 0.6f, 0.4f}, 0.5f, 0.0f});
}

PointLight lightAbove(bool castsShadows) {
  PointLight light{{0.0f, float(kLightHeight), 0.0f}, 50.0f, glm::vec3(1.0f), 800.0f};
  light.castsShadows = castsShadows;
  return light;
}

ReferenceFrame render(const Scene& scene, ShadowMode shadows, Geometry geometry = Geometry::Analytic) {
  ReferenceOptions options;
  options.shadows = shadows;
  options.geometry = geometry;
  return renderReference(scene, kWidth, kHeight, options);
}

// Where the pixel's camera ray meets the plane y = 0.
dvec3 floorPoint(const Camera& camera, int x, int y) {
  const Ray ray = cameraRay(camera, kWidth, kHeight, x, y);
  return ray.origin - ray.origin.y / ray.direction.y * ray.direction;
}

// Judges each floor pixel of a frame lit by one light against `edge(P)`, the signed distance of its floor point P
// past a shadow's edge (negative inside the shadow), and `lit(P)`, whether the light adds to P unshadowed:
// visibility 0 and black inside, 1 and lit outside, -1 and black where the light adds nothing. Returns how many
// pixels were judged inside and outside the shadow.
std::pair<int, int> checkFloor(const Scene& scene, const ReferenceFrame& frame,
                               const std::function<double(const dvec3&)>& edge,
                               const std::function<bool(const dvec3&)>& lit) {
  int inside = 0, outside = 0;
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const size_t i = size_t(y) * kWidth + x;
      if (frame.objectIds[i] != 0) continue;
      const dvec3 P = floorPoint(scene.camera, x, y);
      const double past = edge(P);
      if (std::abs(past) < kBand) continue;
      CAPTURE(P.x);
      CAPTURE(P.z);
      const float red = frame.radiance.at(x, y)[0];
      if (!lit(P)) {
        CHECK(frame.visibility[i] == -1.0f);
        CHECK(red == 0.0f);
      } else if (past < 0.0) {
        ++inside;
        CHECK(frame.visibility[i] == 0.0f);
        CHECK(red == 0.0f);
      } else {
        ++outside;
        CHECK(frame.visibility[i] == 1.0f);
        CHECK(red > 0.0f);
      }
    }
  }
  return {inside, outside};
}

// The facets of a tessellated sphere shadow the points whose interpolated normal faces the light while their facet
// does not: a band along the terminator within about one facet's angle of it, 2 pi / 64 for makeSphereMesh().
const double kFacetTerminator = std::sin(2.0 * kPi / 64.0);

// The sphere's shadow on itself: judged at the pixel's point on the exact sphere, with the light seen in direction
// `towards(P)` from P, a pixel has visibility 0 only where n.l < `terminator` (0 for the exact sphere: nowhere).
void checkSelfShadow(const Scene& scene, const ReferenceFrame& frame, const std::function<dvec3(const dvec3&)>& towards,
                     double terminator) {
  const dvec3 centre(0.0, kSphereHeight, 0.0);
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const size_t i = size_t(y) * kWidth + x;
      if (frame.objectIds[i] != 1 || frame.visibility[i] != 0.0f) continue;
      // The nearer root of |o + t d - c|^2 = r^2; a mesh inscribed in the sphere is hit only by rays that meet it.
      const Ray ray = cameraRay(scene.camera, kWidth, kHeight, x, y);
      const dvec3 oc = ray.origin - centre;
      const double b = glm::dot(oc, ray.direction);
      const double t = -b - std::sqrt(b * b - glm::dot(oc, oc) + kRadius * kRadius);
      const dvec3 P = ray.origin + t * ray.direction;
      CAPTURE(x);
      CAPTURE(y);
      CHECK(glm::dot((P - centre) / kRadius, towards(P)) < terminator);
    }
  }
}

// The radius of the sphere's shadow on the floor under the light above it: the cone from the light tangent to the
// sphere has sin a = r / (H - h) (the tangent line is perpendicular to the radius), and meets the floor at H tan a.
double shadowDiskRadius() {
  const double d = kLightHeight - kSphereHeight;
  return kLightHeight * kRadius / std::sqrt(d * d - kRadius * kRadius);
}

double fromAxis(const dvec3& P) { return std::hypot(P.x, P.z); }

bool always(const dvec3&) { return true; }

}  // namespace

TEST_CASE("reference shadows: a sphere under a point light casts the disk its tangent cone cuts from the floor") {
  Scene s = floorScene();
  addSphere(s);
  s.lights = {lightAbove(false)};
  const double R = shadowDiskRadius();
  for (const Geometry geometry : {Geometry::Analytic, Geometry::Meshes}) {
    const std::string name = toString(geometry);
    CAPTURE(name);
    const ReferenceFrame frame = render(s, ShadowMode::On, geometry);
    const auto [inside, outside] = checkFloor(s, frame, [&](const dvec3& P) { return fromAxis(P) - R; }, always);
    MESSAGE(name << ": " << inside << " floor pixels in the shadow, " << outside << " outside");
    CHECK(inside > 500);
    CHECK(outside > 5000);
    checkSelfShadow(s, frame, [](const dvec3& P) { return glm::normalize(dvec3(0.0, kLightHeight, 0.0) - P); },
                    geometry == Geometry::Analytic ? 0.0 : kFacetTerminator);
  }
}

TEST_CASE("reference shadows: a shadow ray stops at the point light: a surface beyond it casts nothing") {
  Scene s = floorScene();
  addSphere(s);
  // A 4 x 4 ceiling just above the light, facing down: the camera above it sees its back, culled, and sees through.
  const glm::mat4 ceiling = glm::translate(glm::mat4(1.0f), {0.0f, float(kLightHeight + 0.5), 0.0f});
  s.addShape(Shape::Plane, glm::scale(turnedOver(ceiling), {4.0f, 1.0f, 4.0f}), Material{});
  s.lights = {lightAbove(false)};
  const double R = shadowDiskRadius();
  for (const Geometry geometry : {Geometry::Analytic, Geometry::Meshes}) {
    const std::string name = toString(geometry);
    CAPTURE(name);
    const ReferenceFrame frame = render(s, ShadowMode::On, geometry);
    const auto [inside, outside] = checkFloor(s, frame, [&](const dvec3& P) { return fromAxis(P) - R; }, always);
    CHECK(inside > 500);
    CHECK(outside > 5000);
  }
}

TEST_CASE("reference shadows: a spot light's shadow, and no visibility outside its cone") {
  Scene s = floorScene();
  addSphere(s);
  PointLight spot = lightAbove(false);
  const double outer = 25.0 * kPi / 180.0;
  spot.spot = SpotCone{{0.0f, -1.0f, 0.0f}, 0.0f, float(outer)};
  s.lights = {spot};
  // The cone's edge on the floor, straight below the light: H tan(outer).
  const double coneRadius = kLightHeight * std::tan(outer), R = shadowDiskRadius();
  const ReferenceFrame frame = render(s, ShadowMode::On);
  const auto edge = [&](const dvec3& P) {
    const double rho = fromAxis(P);
    return std::abs(rho - coneRadius) < kBand ? 0.0 : rho - R;  // the cone's edge is not judged either
  };
  const auto [inside, outside] = checkFloor(s, frame, edge, [&](const dvec3& P) { return fromAxis(P) < coneRadius; });
  CHECK(inside > 500);
  CHECK(outside > 500);
}

TEST_CASE("reference shadows: a sphere under a slanted directional light casts an ellipse") {
  Scene s = floorScene();
  addSphere(s);
  DirectionalLight sun;
  sun.direction = glm::normalize(glm::vec3(1.2f, -1.5f, 0.4f));
  sun.illuminance = 3.0f;
  s.directionalLights = {sun};
  // A floor point is in the shadow where the line from it towards the light passes within r of the sphere's
  // centre, ahead of it: the ellipse where the cylinder of the sphere's parallel shadow rays meets the floor.
  const dvec3 centre(0.0, kSphereHeight, 0.0), L = -glm::normalize(dvec3(sun.direction));
  const auto edge = [&](const dvec3& P) {
    const dvec3 w = centre - P;
    const double along = glm::dot(w, L);
    if (along <= 0.0) return std::numeric_limits<double>::infinity();
    return std::sqrt(std::max(0.0, glm::dot(w, w) - along * along)) - kRadius;
  };
  for (const Geometry geometry : {Geometry::Analytic, Geometry::Meshes}) {
    const std::string name = toString(geometry);
    CAPTURE(name);
    const ReferenceFrame frame = render(s, ShadowMode::On, geometry);
    const auto [inside, outside] = checkFloor(s, frame, edge, always);
    CHECK(inside > 500);
    CHECK(outside > 5000);
    checkSelfShadow(s, frame, [&](const dvec3&) { return L; }, geometry == Geometry::Analytic ? 0.0 : kFacetTerminator);
  }
}

TEST_CASE("reference shadows: shadow rays meet both faces: a card casts the same square face up or face down") {
  // A square card of side a, h above the floor, under the light H above: its shadow, by similar triangles, is the
  // square of side a H / (H - h).
  const double side = 1.5, height = 3.0, shadowHalf = 0.5 * side * kLightHeight / (kLightHeight - height);
  for (const bool faceDown : {false, true}) {
    CAPTURE(faceDown);
    Scene s = floorScene();
    glm::mat4 card = glm::translate(glm::mat4(1.0f), {0.0f, float(height), 0.0f});
    if (faceDown) card = turnedOver(card);  // the camera sees its back: culled
    s.addShape(Shape::Plane, glm::scale(card, {float(side), 1.0f, float(side)}), Material{});
    s.lights = {lightAbove(false)};
    for (const Geometry geometry : {Geometry::Analytic, Geometry::Meshes}) {
      const std::string name = toString(geometry);
      CAPTURE(name);
      const ReferenceFrame frame = render(s, ShadowMode::On, geometry);
      const auto edge = [&](const dvec3& P) { return std::max(std::abs(P.x), std::abs(P.z)) - shadowHalf; };
      const auto [inside, outside] = checkFloor(s, frame, edge, always);
      CHECK(inside > 500);
      CHECK(outside > 5000);
    }
  }
}

TEST_CASE("reference shadows: ShadowMode::None and lights that do not cast leave the frame as it was") {
  Scene s = floorScene();
  addSphere(s);
  DirectionalLight sun;
  sun.direction = glm::normalize(glm::vec3(1.0f, -2.0f, 0.5f));
  sun.castsShadows = false;
  s.directionalLights = {sun};
  s.lights = {lightAbove(false)};
  s.ambient = glm::vec3(0.05f);
  ReferenceOptions defaults;  // but for the geometry, as render() has it
  defaults.geometry = Geometry::Analytic;
  const ReferenceFrame before = renderReference(s, kWidth, kHeight, defaults);
  CHECK(before.visibility.empty());
  const ReferenceFrame none = render(s, ShadowMode::None);
  CHECK(none.visibility.empty());
  const ReferenceFrame noCaster = render(s, ShadowMode::Auto);
  CHECK(noCaster.radiance.pixels == before.radiance.pixels);
  CHECK(none.radiance.pixels == before.radiance.pixels);
  CHECK(std::all_of(noCaster.visibility.begin(), noCaster.visibility.end(), [](float v) { return v == -1.0f; }));

  // Both lights casting: no pixel gains light, those both reach keep exactly what they had, and some lose light.
  const ReferenceFrame on = render(s, ShadowMode::On);
  REQUIRE(on.visibility.size() == on.objectIds.size());
  int darker = 0;
  for (size_t i = 0; i < on.visibility.size(); ++i) {
    for (size_t c = 0; c < 3; ++c) {
      const float shadowed = on.radiance.pixels[4 * i + c], open = before.radiance.pixels[4 * i + c];
      CHECK(shadowed <= open);
      if (on.visibility[i] == 1.0f) CHECK(shadowed == open);
    }
    darker += on.visibility[i] >= 0.0f && on.visibility[i] < 1.0f;
  }
  CHECK(darker > 500);
  // Some floor pixels are in the shadow of one light only: half the casting lights that add to them reach them.
  CHECK(std::count(on.visibility.begin(), on.visibility.end(), 0.5f) > 100);
}

TEST_CASE("reference shadows: under Auto a light casts as the scene says, under On every light casts") {
  Scene s = floorScene();
  addSphere(s);
  s.lights = {lightAbove(false)};
  const ReferenceFrame open = render(s, ShadowMode::None);
  const ReferenceFrame sceneSaysNo = render(s, ShadowMode::Auto), on = render(s, ShadowMode::On);
  CHECK(sceneSaysNo.radiance.pixels == open.radiance.pixels);
  CHECK(std::count(sceneSaysNo.visibility.begin(), sceneSaysNo.visibility.end(), -1.0f) == kWidth * kHeight);
  CHECK(std::count(on.visibility.begin(), on.visibility.end(), 0.0f) > 500);
  CHECK(on.radiance.pixels != open.radiance.pixels);

  s.lights[0].castsShadows = true;
  const ReferenceFrame sceneSaysYes = render(s, ShadowMode::Auto);
  CHECK(sceneSaysYes.radiance.pixels == on.radiance.pixels);
  CHECK(sceneSaysYes.visibility == on.visibility);
  const ReferenceFrame none = render(s, ShadowMode::None);
  CHECK(none.radiance.pixels == open.radiance.pixels);
  CHECK(none.visibility.empty());
}
