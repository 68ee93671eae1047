// The reference's BLEND layers against composites computed here: a pane over a lit floor shows alpha of the pane
// and 1 - alpha of the floor (from frames of the pane made opaque and of the floor alone, and from the BRDF at one
// point), two panes composite front to back whichever the scene lists first, a pane casts a shadow only from alpha
// 0.5 up, a double-sided pane composites from behind too, and the walk through the layers stops at its bound.
#include <doctest/doctest.h>

#include <cstddef>
#include <functional>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "core/scene/scene.hpp"
#include "reference/directional_light.hpp"
#include "reference/point_light.hpp"
#include "reference/raycast.hpp"
#include "reference/reference_renderer.hpp"

using namespace pbr;
using namespace pbr::reference;

namespace {

constexpr int kWidth = 32, kHeight = 18;
constexpr size_t kFloor = 0, kPane = 1;
const glm::vec3 kRed(0.9f, 0.2f, 0.1f), kBlue(0.1f, 0.3f, 0.9f);

glm::mat4 placed(const glm::vec3& at, const glm::vec3& scale) {
  return glm::scale(glm::translate(glm::mat4(1.0f), at), scale);
}

// A horizontal square of side `side` at `at`, facing up (or down, turned over half a turn about x).
glm::mat4 pane(const glm::vec3& at, float side, bool faceDown = false) {
  glm::mat4 m = glm::translate(glm::mat4(1.0f), at);
  if (faceDown) m = glm::rotate(m, float(kPi), glm::vec3(1.0f, 0.0f, 0.0f));
  return glm::scale(m, {side, 1.0f, side});
}

Material blend(const glm::vec3& color, float alpha) {
  Material m{color, 0.4f, 0.0f};
  m.alpha = alpha;
  m.alphaMode = AlphaMode::Blend;
  return m;
}

// A 16 x 16 grey floor (object 0) seen from above, lit by a point light over the middle and a slanted sun, both
// casting, and faint ambient light.
Scene floorScene(bool ambient = true) {
  Scene s;
  s.name = "transparency";
  s.camera.position = {0.0f, 8.0f, 3.0f};
  s.camera.target = {0.0f, 0.0f, 0.0f};
  s.camera.fovYDeg = 45.0f;
  s.camera.nearPlane = 0.5f;
  s.camera.farPlane = 40.0f;
  s.ambient = glm::vec3(ambient ? 0.03f : 0.0f);
  s.addShape(Shape::Plane, placed({0, 0, 0}, {16.0f, 1.0f, 16.0f}), Material{glm::vec3(0.5f), 0.7f, 0.0f});
  PointLight light{{0.3f, 6.0f, 0.2f}, 50.0f, glm::vec3(1.0f), 800.0f};
  light.castsShadows = true;
  s.lights = {light};
  DirectionalLight sun;
  sun.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
  sun.illuminance = 2.0f;
  s.directionalLights = {sun};
  return s;
}

ReferenceFrame render(const Scene& scene, Geometry geometry, ShadowMode shadows) {
  ReferenceOptions options;
  options.geometry = geometry;
  options.shadows = shadows;
  return renderReference(scene, kWidth, kHeight, options);
}

// The scene with object `index` made OPAQUE, or removed.
Scene opaque(Scene s, size_t index) {
  s.objects[index].material.alphaMode = AlphaMode::Opaque;
  return s;
}
Scene without(Scene s, size_t index) {
  s.objects.erase(s.objects.begin() + std::ptrdiff_t(index));
  return s;
}

// Checks each colour channel of pixel i against `want(c)`, composited here in double from float frames: it differs
// from the reference's by the rounding of its inputs, some 1e-7.
void checkPixel(const ReferenceFrame& frame, size_t i, const std::function<double(int)>& want) {
  for (int c = 0; c < 3; ++c) CHECK(frame.radiance.pixels[4 * i + c] == doctest::Approx(want(c)).epsilon(1e-6));
}

float channel(const ReferenceFrame& frame, size_t i, int c) { return frame.radiance.pixels[4 * i + c]; }

const Geometry kGeometries[] = {Geometry::Analytic, Geometry::Meshes};
const ShadowMode kShadowModes[] = {ShadowMode::None, ShadowMode::On};

}  // namespace

TEST_CASE("reference transparency: a 0.3-alpha pane shows 0.3 of its own radiance and 0.7 of the floor's") {
  Scene s = floorScene();
  s.addShape(Shape::Plane, pane({0.0f, 2.5f, 0.0f}, 4.0f), blend(kRed, 0.3f));
  const double a = double(0.3f);
  for (const Geometry geometry : kGeometries) {
    for (const ShadowMode shadows : kShadowModes) {
      CAPTURE(toString(geometry));
      CAPTURE(toString(shadows));
      const ReferenceFrame frame = render(s, geometry, shadows);
      const ReferenceFrame paneAlone = render(opaque(s, kPane), geometry, shadows);
      const ReferenceFrame floorAlone = render(without(s, kPane), geometry, shadows);
      CHECK(frame.truncatedRays == 0);
      int through = 0, beside = 0;
      for (size_t i = 0; i < frame.objectIds.size(); ++i) {
        CAPTURE(i);
        if (frame.objectIds[i] == int(kPane)) {
          // Through the pane: its own radiance as if it were opaque, over the floor's as if it were not there. The
          // first surface's id and visibility are the pane's.
          ++through;
          REQUIRE(paneAlone.objectIds[i] == int(kPane));
          REQUIRE(floorAlone.objectIds[i] == int(kFloor));
          checkPixel(frame, i, [&](int c) {
            return a * channel(paneAlone, i, c) + (1.0 - a) * channel(floorAlone, i, c);
          });
          if (shadows == ShadowMode::On) CHECK(frame.visibility[i] == paneAlone.visibility[i]);
        } else {
          // Beside it, the floor as if the pane were not there, shadow included: 0.3 lets shadow rays through.
          ++beside;
          CHECK(frame.objectIds[i] == floorAlone.objectIds[i]);
          for (int c = 0; c < 4; ++c) CHECK(channel(frame, i, c) == channel(floorAlone, i, c));
          if (shadows == ShadowMode::On) CHECK(frame.visibility[i] == floorAlone.visibility[i]);
        }
      }
      CHECK(through > 30);
      CHECK(beside > 30);
    }
  }
}

TEST_CASE("reference transparency: at one point through the pane, alpha of the pane's BRDF over the floor's") {
  // No ambient light, so that the radiance of each surface is the lights' alone, summed here from the BRDF.
  Scene s = floorScene(false);
  const double height = 2.5;
  s.addShape(Shape::Plane, pane({0.0f, float(height), 0.0f}, 4.0f), blend(kRed, 0.3f));
  const ReferenceFrame frame = render(s, Geometry::Analytic, ShadowMode::On);
  const int x = kWidth / 2, y = kHeight / 2;
  const size_t i = size_t(y) * kWidth + x;
  REQUIRE(frame.objectIds[i] == int(kPane));
  const Ray ray = cameraRay(s.camera, kWidth, kHeight, x, y);
  const dvec3 up(0.0, 1.0, 0.0), V = -ray.direction;
  // What the lights reflect from a point with normal +Y: nothing stands between a light and either point, the pane
  // letting shadow rays through at alpha 0.3.
  auto lit = [&](double planeY, const Material& material) {
    const dvec3 P = ray.origin + (planeY - ray.origin.y) / ray.direction.y * ray.direction;
    const ReferenceMaterial m{dvec3(material.baseColor), double(material.roughness), double(material.metalness)};
    return reflectedRadiance(s.lights[0], P, up, V, m, BrdfForms{}) +
           reflectedRadiance(s.directionalLights[0], up, V, m, BrdfForms{});
  };
  const dvec3 paneColor = lit(height, s.objects[kPane].material), floorColor = lit(0.0, s.objects[kFloor].material);
  const double a = double(0.3f);
  CHECK(frame.visibility[i] == 1.0f);
  checkPixel(frame, i, [&](int c) { return a * paneColor[c] + (1.0 - a) * floorColor[c]; });
}

TEST_CASE("reference transparency: two panes composite front to back whichever the scene lists first") {
  const double aRed = double(0.3f), aBlue = double(0.6f);
  // The red pane above the blue one, overlapping it in part: the camera above sees red over blue where both are.
  const glm::mat4 high = pane({-0.4f, 2.5f, 0.0f}, 3.5f), low = pane({0.6f, 1.5f, 0.3f}, 3.5f);
  Scene redFirst = floorScene(), blueFirst = floorScene();
  redFirst.addShape(Shape::Plane, high, blend(kRed, 0.3f));
  redFirst.addShape(Shape::Plane, low, blend(kBlue, 0.6f));
  blueFirst.addShape(Shape::Plane, low, blend(kBlue, 0.6f));
  blueFirst.addShape(Shape::Plane, high, blend(kRed, 0.3f));
  for (const Geometry geometry : kGeometries) {
    CAPTURE(toString(geometry));
    // Without shadows, each surface's radiance is the same whatever else stands in the scene: that of a frame
    // with it alone opaque in front, or of the floor alone.
    const ShadowMode shadows = ShadowMode::None;
    const ReferenceFrame a = render(redFirst, geometry, shadows), b = render(blueFirst, geometry, shadows);
    const ReferenceFrame red = render(opaque(without(redFirst, 2), 1), geometry, shadows);
    const ReferenceFrame blue = render(opaque(without(redFirst, 1), 1), geometry, shadows);
    const ReferenceFrame floor = render(without(without(redFirst, 2), 1), geometry, shadows);
    // The same layers in the same depth order give the same sums: bit for bit.
    CHECK(a.radiance.pixels == b.radiance.pixels);
    int both = 0;
    for (size_t i = 0; i < a.objectIds.size(); ++i) {
      CAPTURE(i);
      const bool inRed = red.objectIds[i] == 1, inBlue = blue.objectIds[i] == 1;
      both += inRed && inBlue;
      checkPixel(a, i, [&](int c) {
        const double behindRed = inBlue ? aBlue * channel(blue, i, c) + (1.0 - aBlue) * channel(floor, i, c)
                                        : double(channel(floor, i, c));
        return inRed ? aRed * channel(red, i, c) + (1.0 - aRed) * behindRed : behindRed;
      });
      // The first surface: the red pane in front where the ray crosses it.
      CHECK(a.objectIds[i] == (inRed ? 1 : inBlue ? 2 : 0));
      CHECK(b.objectIds[i] == (inRed ? 2 : inBlue ? 1 : 0));
    }
    CHECK(both > 20);
  }
}

TEST_CASE("reference transparency: a BLEND pane stops shadow rays from alpha 0.5 up, as an opaque one does") {
  Scene s = floorScene();
  s.directionalLights.clear();
  s.lights[0].position = {0.0f, 6.0f, 0.0f};
  s.addShape(Shape::Plane, pane({0.0f, 3.0f, 0.0f}, 1.5f), blend(kRed, 0.3f));
  for (const Geometry geometry : kGeometries) {
    CAPTURE(toString(geometry));
    const ReferenceFrame open = render(without(s, kPane), geometry, ShadowMode::On);
    const ReferenceFrame shadowed = render(opaque(s, kPane), geometry, ShadowMode::On);
    for (const float alpha : {0.3f, 0.4999f, 0.5f, 0.8f}) {
      CAPTURE(alpha);
      s.objects[kPane].material.alpha = alpha;
      const ReferenceFrame frame = render(s, geometry, ShadowMode::On);
      const ReferenceFrame& floor = alpha >= 0.5f ? shadowed : open;
      int dark = 0;
      for (size_t i = 0; i < frame.objectIds.size(); ++i) {
        if (frame.objectIds[i] != int(kFloor)) continue;
        CAPTURE(i);
        // The floor seen beside the pane: as without it below 0.5, as under the opaque pane from 0.5 up.
        CHECK(floor.objectIds[i] == int(kFloor));
        CHECK(frame.visibility[i] == floor.visibility[i]);
        for (int c = 0; c < 3; ++c) CHECK(channel(frame, i, c) == channel(floor, i, c));
        dark += frame.visibility[i] == 0.0f;
      }
      if (alpha >= 0.5f) {
        CHECK(dark > 10);
      } else {
        CHECK(dark == 0);
      }
    }
  }
}

TEST_CASE("reference transparency: a BLEND surface of alpha 1 is an opaque one, and other modes ignore alpha") {
  Scene s = floorScene();
  s.addShape(Shape::Plane, pane({0.0f, 2.5f, 0.0f}, 4.0f), blend(kRed, 1.0f));
  // Alpha factors and cutoffs of OPAQUE and MASK surfaces change nothing: the reference reads no texture to cut.
  Scene masked = opaque(s, kPane);
  masked.objects[kFloor].material.alpha = 0.2f;
  masked.objects[kPane].material.alpha = 0.1f;
  masked.objects[kPane].material.alphaMode = AlphaMode::Mask;
  masked.objects[kPane].material.alphaCutoff = 0.9f;
  for (const Geometry geometry : kGeometries) {
    CAPTURE(toString(geometry));
    const ReferenceFrame expected = render(opaque(s, kPane), geometry, ShadowMode::On);
    for (const Scene* scene : {&s, &masked}) {
      const ReferenceFrame frame = render(*scene, geometry, ShadowMode::On);
      CHECK(frame.radiance.pixels == expected.radiance.pixels);
      CHECK(frame.objectIds == expected.objectIds);
      CHECK(frame.visibility == expected.visibility);
    }
  }
}

TEST_CASE("reference transparency: a double-sided BLEND pane composites seen from behind, one-sided is not seen") {
  // The pane faces down, away from the camera above it; double-sided, its back faces the camera and the light.
  // Analytic shapes have no back faces for the camera (raycast.hpp), so the mesh geometry renders this.
  Scene s = floorScene();
  s.addShape(Shape::Plane, pane({0.0f, 2.5f, 0.0f}, 4.0f, true), blend(kRed, 0.3f));
  s.objects[kPane].material.doubleSided = true;
  const double a = double(0.3f);
  const ReferenceFrame frame = render(s, Geometry::Meshes, ShadowMode::On);
  const ReferenceFrame paneAlone = render(opaque(s, kPane), Geometry::Meshes, ShadowMode::On);
  const ReferenceFrame floorAlone = render(without(s, kPane), Geometry::Meshes, ShadowMode::On);
  int through = 0;
  for (size_t i = 0; i < frame.objectIds.size(); ++i) {
    CAPTURE(i);
    if (frame.objectIds[i] != int(kPane)) {
      for (int c = 0; c < 3; ++c) CHECK(channel(frame, i, c) == channel(floorAlone, i, c));
      continue;
    }
    ++through;
    REQUIRE(paneAlone.objectIds[i] == int(kPane));
    CHECK(channel(paneAlone, i, 0) > channel(paneAlone, i, 2));  // its back is lit: red, not black
    checkPixel(frame, i, [&](int c) {
      return a * channel(paneAlone, i, c) + (1.0 - a) * channel(floorAlone, i, c);
    });
  }
  CHECK(through > 30);

  s.objects[kPane].material.doubleSided = false;
  const ReferenceFrame culled = render(s, Geometry::Meshes, ShadowMode::On);
  CHECK(culled.radiance.pixels == floorAlone.radiance.pixels);
  CHECK(culled.objectIds == floorAlone.objectIds);
}

TEST_CASE("reference transparency: a ray composites at most kMaxBlendLayers layers and counts those it drops") {
  // Panes over the whole frame, stacked far apart against the gap a ray leaves past each (1e-6 of the scene).
  auto stack = [](int panes) {
    Scene s = floorScene(false);
    for (int k = 0; k < panes; ++k) {
      s.addShape(Shape::Plane, pane({0.0f, 0.5f + 0.02f * float(k), 0.0f}, 16.0f), blend(kRed, 0.01f));
    }
    return s;
  };
  const ReferenceFrame full = render(stack(kMaxBlendLayers), Geometry::Analytic, ShadowMode::None);
  CHECK(full.truncatedRays == 0);
  const ReferenceFrame over = render(stack(kMaxBlendLayers + 1), Geometry::Analytic, ShadowMode::None);
  CHECK(over.truncatedRays == kWidth * kHeight);
  // The nearest pane is the first surface everywhere.
  for (const int id : over.objectIds) CHECK(id == kMaxBlendLayers + 1);
}
