// Shadow maps (shadows/, shaders/shadows/shadow_sample.glsl) against geometry computed here: a box's shadow under a sun
// against its analytic projection, a plane's shadow (the planes that hide nothing visible left out of the views) and a
// floor between a lamp and what stands on it, acne and peter-panning at a low sun, alpha-mask cut-outs, lights that do
// not cast, clustered against brute force with shadows on, agreement with the reference's shadow rays, coarser sphere
// casters against the whole mesh, and the shadows debug view (`--debug shadows`) against the reference.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "app/accuracy/shadow_metrics.hpp"
#include "core/scene/mesh.hpp"
#include "reference/raycast.hpp"
#include "reference/reference_renderer.hpp"
#include "renderer/offscreen.hpp"
#include "renderer/renderer.hpp"
#include "tests/gl_test_context.hpp"

using glm::dvec3;

namespace {

constexpr double kFloorSize = 40.0;

pbr::Material grey(float base) {
  pbr::Material m;
  m.baseColor = glm::vec3(base);
  m.roughness = 0.8f;
  return m;
}

// A floor under a unit box standing on it at the origin, seen from straight above the point (cameraX, 0, 0). The
// floor is a plane, which no light's view draws while nothing visible lies below it (CasterPlane), or with
// `slabFloor` a box 10 cm deep whose top is at y = 0, which every view draws.
pbr::Scene boxScene(const glm::vec3& sunDirection, float cameraHeight, float cameraX = 0.0f, bool slabFloor = false) {
  pbr::Scene s;
  s.name = "shadow box";
  s.camera.position = {cameraX, cameraHeight, 0.0f};
  s.camera.target = {cameraX, 0.0f, 0.0f};
  s.camera.up = {0.0f, 0.0f, -1.0f};
  s.camera.fovYDeg = 45.0f;
  if (slabFloor) {
    s.addShape(pbr::Shape::Box,
               glm::scale(glm::translate(glm::mat4(1.0f), {0.0f, -0.05f, 0.0f}), glm::vec3(float(kFloorSize), 0.1f,
                                                                                          float(kFloorSize))),
               grey(0.6f));
  } else {
    s.addShape(pbr::Shape::Plane, glm::scale(glm::mat4(1.0f), glm::vec3(float(kFloorSize))), grey(0.6f));
  }
  s.addShape(pbr::Shape::Box, glm::translate(glm::mat4(1.0f), {0.0f, 0.5f, 0.0f}), grey(0.8f));
  s.directionalLights = {{glm::normalize(sunDirection), glm::vec3(1.0f), 2.0f}};
  return s;
}

// Whether the ray from `p` along `d` meets the box [lo, hi] (slab test).
bool rayMeetsBox(const dvec3& p, const dvec3& d, const dvec3& lo, const dvec3& hi) {
  double t0 = 0.0, t1 = 1e30;
  for (int a = 0; a < 3; ++a) {
    if (std::abs(d[a]) < 1e-15) {
      if (p[a] < lo[a] || p[a] > hi[a]) return false;
      continue;
    }
    double ta = (lo[a] - p[a]) / d[a], tb = (hi[a] - p[a]) / d[a];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
  return t0 <= t1;
}

// The caster over the floor: boxScene's unit box, or a flat square (a box of no height).
struct Caster {
  dvec3 lo, hi;
};
constexpr Caster kUnitBox{{-0.5, 0.0, -0.5}, {0.5, 1.0, 0.5}};

// The floor point a pixel sees, or nothing where it sees the caster (or nothing).
std::optional<dvec3> floorPoint(const pbr::Scene& scene, glm::ivec2 size, int x, int y, const Caster& c = kUnitBox) {
  const pbr::reference::Ray ray = pbr::reference::cameraRay(scene.camera, size.x, size.y, x, y);
  if (rayMeetsBox(ray.origin, ray.direction, c.lo, c.hi)) return std::nullopt;
  if (ray.direction.y >= 0.0) return std::nullopt;
  const double t = -ray.origin.y / ray.direction.y;
  return ray.origin + ray.direction * t;
}

// Analytic: the caster shadows floor point p from a sun travelling along d.
bool inBoxShadow(const dvec3& p, const dvec3& d, const Caster& c = kUnitBox) {
  return rayMeetsBox(p + dvec3(0.0, 1e-9, 0.0), -d, c.lo, c.hi);
}

// The world size of the coarsest cascade texel of a rendered frame's sun, as its plan reports it; a cascade of at
// least 256 texels over this 40 m floor seen from a few metres up, so under 5 cm.
double largestCascadeTexel(const pbr::RenderedFrames& frame) {
  const double texel = frame.stats.shadows.cascadeTexelMax;
  REQUIRE(texel > 0.0);
  CHECK(texel < 0.05);
  return texel;
}

struct OutlineResult {
  int lit = 0, shadowed = 0, wrong = 0;  // pixels compared: lit and shadowed as the geometry says; misclassified
};

// Compares a sun-shadowed box frame with the analytic shadow, skipping floor points within `band` (world units)
// of the outline: there the filter's penumbra and the map's texels may decide either way.
OutlineResult compareOutline(const pbr::Scene& scene, glm::ivec2 size, const std::vector<float>& visibility,
                             double band, const Caster& caster = kUnitBox) {
  const dvec3 d = glm::normalize(dvec3(scene.directionalLights[0].direction));
  OutlineResult r;
  for (int y = 0; y < size.y; ++y) {
    for (int x = 0; x < size.x; ++x) {
      const std::optional<dvec3> p = floorPoint(scene, size, x, y, caster);
      const double v = visibility[size_t(y) * size.x + x];
      if (!p || v < 0.0) continue;
      const bool shadowed = inBoxShadow(*p, d, caster);
      bool nearOutline = false;
      for (int k = 0; k < 16 && !nearOutline; ++k) {
        const double a = k * 3.14159265358979 / 8.0;
        nearOutline = inBoxShadow(*p + band * dvec3(std::cos(a), 0.0, std::sin(a)), d, caster) != shadowed;
      }
      if (nearOutline) continue;
      (shadowed ? r.shadowed : r.lit) += 1;
      if ((v < 0.5) != shadowed) ++r.wrong;
    }
  }
  return r;
}

// compareOutline for a frame with shadows (`lit`) and the same without (`none`) under the scene's sun, with a band
// of 1.5 of the frame's coarsest cascade texels, stretched by 1 / cos(theta) from the light's image plane onto the
// floor.
OutlineResult sunOutline(const pbr::Scene& scene, glm::ivec2 size, const pbr::RenderedFrames& lit,
                         const pbr::RenderedFrames& none, const Caster& caster = kUnitBox) {
  const double texel = largestCascadeTexel(lit);
  const double cosTheta = -glm::normalize(dvec3(scene.directionalLights[0].direction)).y;
  return compareOutline(scene, size, pbr::visibilityRatio(lit.hdr, none.hdr), 1.5 * texel / cosTheta, caster);
}

// A floor and a sphere of radius 0.6 above it, seen from above and in front: the spot and point light scenes'.
pbr::Scene sphereOverFloor() {
  pbr::Scene s;
  s.camera.position = {0.0f, 4.0f, 6.0f};
  s.camera.target = {0.0f, 0.5f, 0.0f};
  s.addShape(pbr::Shape::Plane, glm::scale(glm::mat4(1.0f), glm::vec3(20.0f)), grey(0.6f));
  s.addShape(pbr::Shape::Sphere, glm::scale(glm::translate(glm::mat4(1.0f), {0.3f, 1.2f, 0.0f}), glm::vec3(1.2f)),
             grey(0.7f));
  return s;
}

// A casting point light above and beside the sphere of sphereOverFloor.
pbr::PointLight pointOverSphere() {
  pbr::PointLight l;
  l.position = {-0.8f, 3.0f, 0.6f};
  l.radius = 12.0f;
  l.luminousPower = 400.0f;
  l.castsShadows = true;
  return l;
}

// Whether every pixel within `band` pixels of (x, y) is the floor (object 0) in the reference's state `state`
// (0 shadowed, 1 lit).
bool uniformAround(const pbr::reference::ReferenceFrame& ref, glm::ivec2 size, int x, int y, int band, float state) {
  for (int dy = -band; dy <= band; ++dy) {
    for (int dx = -band; dx <= band; ++dx) {
      const int u = x + dx, v = y + dy;
      if (u < 0 || v < 0 || u >= size.x || v >= size.y) return false;
      const size_t i = size_t(v) * size_t(size.x) + size_t(u);
      if (ref.objectIds[i] != 0 || ref.visibility[i] != state) return false;
    }
  }
  return true;
}

}  // namespace

TEST_CASE("shadows: a box's shadow under a sun is its analytic projection within 1.5 texels, in both projections") {
  PBR_REQUIRE_GL();
  const pbr::ShaderLibrary shaders;
  const glm::ivec2 size{192, 192};
  const glm::vec3 sun{-0.45f, -1.0f, 0.3f};
  pbr::Scene perspective = boxScene(sun, 6.0f);
  const auto seenOrthographic = [](pbr::Scene s) {
    s.camera.orthographic = true;
    s.camera.orthoHalfHeight = 2.5f;
    return s;
  };
  // Seen along parallel rays, the cascades fit the orthographic view's box of the occupied depth range.
  pbr::Scene orthographic = seenOrthographic(perspective);
  // A floor seen from straight above with the box left of the view: every visible point lies at one view depth, and
  // the sun throws the box's shadow into the view.
  pbr::Scene headOn = boxScene({0.9f, -1.0f, 0.2f}, 6.0f, 3.2f);
  pbr::FrameOptions shadowed, plain;
  plain.shadows.mode = pbr::ShadowMode::None;
  for (const auto& [scene, filter] : {std::pair{perspective, pbr::ShadowFilter::Hard},
                                      std::pair{perspective, pbr::ShadowFilter::Pcf3x3},
                                      std::pair{orthographic, pbr::ShadowFilter::Pcf3x3},
                                      std::pair{headOn, pbr::ShadowFilter::Pcf3x3},
                                      std::pair{seenOrthographic(headOn), pbr::ShadowFilter::Pcf3x3}}) {
    CAPTURE(scene.camera.orthographic);
    CAPTURE(scene.camera.position.x);
    CAPTURE(std::string(pbr::toString(filter)));
    shadowed.shadows.filter = filter;
    const pbr::RenderedFrames lit = pbr::renderOffscreen(shaders, scene, size, shadowed, 1);
    const pbr::RenderedFrames none = pbr::renderOffscreen(shaders, scene, size, plain, 1);
    CHECK(lit.stats.shadows.shadowedLights == 1);
    const OutlineResult r = sunOutline(scene, size, lit, none);
    MESSAGE(std::string(pbr::toString(filter)) << ": texel " << largestCascadeTexel(lit) << " m, " << r.lit
                                               << " lit and " << r.shadowed << " shadowed pixels compared, "
                                               << r.wrong << " misclassified");
    CHECK(r.shadowed > 500);
    CHECK(r.lit > 5000);
    CHECK(r.wrong == 0);
  }
}

TEST_CASE("shadows: a low sun leaves no acne on the lit floor, and the box's shadow starts at its base") {
  PBR_REQUIRE_GL();
  const pbr::ShaderLibrary shaders;
  const glm::ivec2 size{160, 160};
  // 80 degrees from the zenith: the floor's depth changes by tan(80) = 5.7 texels per texel in the map.
  const double angle = 80.0 * 3.14159265358979 / 180.0;
  const glm::vec3 sun{float(std::sin(angle)), -float(std::cos(angle)), 0.0f};
  // Seen from above x = 2.5: the floor beside the face the light leaves is in view, not behind the box's top. A
  // slab, so that the maps hold the floor's own depths, which acne would come from.
  const pbr::Scene scene = boxScene(sun, 7.0f, 2.5f, true);
  pbr::FrameOptions plain;
  plain.shadows.mode = pbr::ShadowMode::None;
  const pbr::RenderedFrames none = pbr::renderOffscreen(shaders, scene, size, plain, 1);
  for (const pbr::ShadowFilter filter :
       {pbr::ShadowFilter::Hard, pbr::ShadowFilter::Pcf3x3, pbr::ShadowFilter::Poisson16}) {
    CAPTURE(std::string(pbr::toString(filter)));
    pbr::FrameOptions options;
    options.shadows.filter = filter;
    const pbr::RenderedFrames shadowed = pbr::renderOffscreen(shaders, scene, size, options, 1);
    const std::vector<float> v = pbr::visibilityRatio(shadowed.hdr, none.hdr);
    const double texel = largestCascadeTexel(shadowed);
    const dvec3 d = glm::normalize(dvec3(sun));
    int lit = 0, dark = 0, gapChecked = 0, gapLit = 0;
    for (int y = 0; y < size.y; ++y) {
      for (int x = 0; x < size.x; ++x) {
        const std::optional<dvec3> p = floorPoint(scene, size, x, y);
        const double vis = v[size_t(y) * size.x + x];
        if (!p || vis < 0.0) continue;
        // The shadow falls along +x from the box's face at x = 0.5; its sides are at z = +-0.5.
        const bool besideShadow = std::abs(std::abs(p->z) - 0.5) < 4.0 * texel && p->x > 0.0;
        if (!inBoxShadow(*p, d) && !besideShadow && std::abs(p->x) > 0.5 + 4.0 * texel) {
          ++lit;
          if (vis < 0.9) ++dark;
        }
        // Floor just past the face the light leaves (2 texels on, in the middle of the face): in shadow.
        if (p->x > 0.5 + 2.0 * texel && p->x < 0.5 + 6.0 * texel && std::abs(p->z) < 0.3) {
          ++gapChecked;
          if (vis >= 0.5) ++gapLit;
        }
      }
    }
    MESSAGE(std::string(pbr::toString(filter)) << ": " << dark << " of " << lit << " lit floor pixels below 0.9; "
                                               << gapLit << " of " << gapChecked << " pixels 2-6 texels past the base lit");
    CHECK(lit > 10000);
    CHECK(dark == 0);
    CHECK(gapChecked > 4);
    CHECK(gapLit == 0);
  }
}

TEST_CASE("shadows: a plane casts onto what lies beyond it, and no view draws a plane with nothing visible beyond") {
  PBR_REQUIRE_GL();
  const pbr::ShaderLibrary shaders;
  const glm::ivec2 size{192, 192};
  // A 2 m square roof (a plane, as the floor) 1.5 m over the floor under a sun: the roof hides floor points from
  // it, the floor hides nothing in view.
  const glm::vec3 sun{-0.45f, -1.0f, 0.3f};
  pbr::Scene scene = boxScene(sun, 6.0f);
  scene.objects.pop_back();
  scene.addShape(pbr::Shape::Plane, glm::scale(glm::translate(glm::mat4(1.0f), {0.0f, 1.5f, 0.0f}), glm::vec3(2.0f)),
                 grey(0.8f));
  const Caster roof{{-1.0, 1.5, -1.0}, {1.0, 1.5, 1.0}};
  pbr::FrameOptions shadowed, plain;
  plain.shadows.mode = pbr::ShadowMode::None;
  const pbr::RenderedFrames lit = pbr::renderOffscreen(shaders, scene, size, shadowed, 1);
  const pbr::RenderedFrames none = pbr::renderOffscreen(shaders, scene, size, plain, 1);
  // Each rendered cascade leaves the floor out and draws the roof.
  CHECK(lit.stats.shadows.viewsRendered > 0);
  CHECK(lit.stats.shadows.planesLeftOut == lit.stats.shadows.viewsRendered);
  const OutlineResult r = sunOutline(scene, size, lit, none, roof);
  MESSAGE(r.lit << " lit and " << r.shadowed << " shadowed floor pixels compared, " << r.wrong << " misclassified");
  CHECK(r.shadowed > 1000);
  CHECK(r.lit > 5000);
  CHECK(r.wrong == 0);
}

TEST_CASE("shadows: a plane posed elsewhere is planned from where it now lies") {
  PBR_REQUIRE_GL();
  // A roof starts under the floor, where it hides nothing in view from the sun and is left out; posed 1.5 m over
  // the floor and the box it must be drawn, as a renderer that never saw the first pose draws it.
  const pbr::ShaderLibrary shaders;
  const glm::ivec2 size{96, 96};
  pbr::Scene scene = boxScene({-0.45f, -1.0f, 0.3f}, 6.0f);
  const auto roofAt = [](float y) {
    return glm::scale(glm::translate(glm::mat4(1.0f), {0.0f, y, 0.0f}), glm::vec3(2.0f));
  };
  scene.addShape(pbr::Shape::Plane, roofAt(-1.0f), grey(0.8f));
  pbr::Renderer renderer(shaders, scene, size.x, size.y);
  pbr::Profiler profiler(pbr::TimingMode::Serializing);
  pbr::FrameOptions options;
  options.shadows.cache = false;
  const auto frame = [&] {
    pbr::ImageRgbaF hdr;
    renderer.renderFrame(options, profiler, {nullptr, &hdr});
    return hdr.pixels;
  };
  const auto under = frame();
  const pbr::ShadowStats s = renderer.lightStats().shadows;
  REQUIRE(s.viewsRendered > 0);
  CHECK(s.planesLeftOut == 2 * s.viewsRendered);  // the floor and the roof
  scene.objects.back().transform = roofAt(1.5f);
  renderer.scenePosed({});
  const auto over = frame();
  CHECK(renderer.lightStats().shadows.planesLeftOut == renderer.lightStats().shadows.viewsRendered);  // the floor
  CHECK(over != under);
  CHECK(over == pbr::renderOffscreen(shaders, scene, size, options, 1).hdr.pixels);
}

TEST_CASE("shadows: a floor keeps a lamp under it from what stands on it") {
  PBR_REQUIRE_GL();
  const pbr::ShaderLibrary shaders;
  const glm::ivec2 size{128, 96};
  // The box on the floor plane, seen from the side, and a lamp under the floor beside it, whose light would reach
  // the box's side facing it but for the floor: visible points lie on the far side of the floor from the lamp, so
  // the lamp's views draw the floor.
  pbr::Scene scene = boxScene({0.0f, -1.0f, 0.0f}, 1.0f);
  scene.directionalLights.clear();
  scene.camera.position = {3.0f, 1.2f, 3.0f};
  scene.camera.target = {0.0f, 0.5f, 0.0f};
  scene.camera.up = {0.0f, 1.0f, 0.0f};
  pbr::PointLight lamp;
  lamp.position = {2.0f, -0.5f, 0.0f};
  lamp.radius = 10.0f;
  lamp.luminousPower = 400.0f;
  lamp.castsShadows = true;
  scene.lights = {lamp};
  pbr::FrameOptions shadowed, plain;
  plain.shadows.mode = pbr::ShadowMode::None;
  const pbr::RenderedFrames lit = pbr::renderOffscreen(shaders, scene, size, shadowed, 1);
  const pbr::RenderedFrames none = pbr::renderOffscreen(shaders, scene, size, plain, 1);
  CHECK(lit.stats.shadows.viewsRendered > 0);
  CHECK(lit.stats.shadows.planesLeftOut == 0);
  // Unshadowed, the lamp lights the box's +x face through the floor; the reference's shadow rays meet the floor.
  const std::vector<float> v = pbr::visibilityRatio(lit.hdr, none.hdr);
  pbr::reference::ReferenceOptions referenceOptions;
  referenceOptions.shadows = pbr::ShadowMode::Auto;
  pbr::reference::ReferenceFrame expected = pbr::reference::renderReference(scene, size.x, size.y, referenceOptions);
  REQUIRE(expected.visibility.size() == v.size());
  // The box's pixels (object 1), outside a band of 2 pixels around the reference's changes of state, where its
  // face meets the floor (which the lamp does not light at all) and the filter reaches past the floor's edge.
  for (size_t i = 0; i < expected.visibility.size(); ++i)
    if (expected.objectIds[i] != 1) expected.visibility[i] = -1.0f;
  const pbr::ShadowAgreement a = pbr::compareShadowState(v, expected, 2);
  MESSAGE((a.compared - a.misclassified) << " of " << a.compared << " box pixels agree, " << a.shadowed
                                       << " shadowed in the reference");
  CHECK(a.shadowed > 300);
  CHECK(a.misclassified == 0);
}

TEST_CASE("shadows: an alpha-masked caster casts its cut-out") {
  PBR_REQUIRE_GL();
  const pbr::ShaderLibrary shaders;
  const glm::ivec2 size{128, 128};
  pbr::Scene scene;
  scene.camera.position = {0.0f, 8.0f, 0.0f};
  scene.camera.target = {0.0f, 0.0f, 0.0f};
  scene.camera.up = {0.0f, 0.0f, -1.0f};
  scene.addShape(pbr::Shape::Plane, glm::scale(glm::mat4(1.0f), glm::vec3(30.0f)), grey(0.6f));
  // A 2 x 2 card at height 2 whose texture is transparent on one half (u < 0.5) and opaque on the other.
  pbr::TextureData card;
  card.name = "half-alpha card";
  card.width = card.height = 8;
  for (int y = 0; y < 8; ++y) {
    for (int x = 0; x < 8; ++x) {
      const uint8_t alpha = x < 4 ? 0 : 255;
      card.rgba.insert(card.rgba.end(), {200, 200, 200, alpha});
    }
  }
  card.srgb = true;
  card.minFilter = card.magFilter = 0x2600;  // GL_NEAREST: the halves stay sharp
  scene.textures.push_back(card);
  pbr::Material masked = grey(0.8f);
  masked.baseColorTexture = 0;
  masked.alphaMode = pbr::AlphaMode::Mask;
  masked.doubleSided = true;
  const glm::mat4 cardTransform = glm::scale(glm::translate(glm::mat4(1.0f), {0.0f, 2.0f, 0.0f}), glm::vec3(2.0f));
  scene.addShape(pbr::Shape::Plane, cardTransform, masked);
  // A sun at 45 degrees along +x: the card's shadow falls on x in [1, 3], clear of the card as seen from above.
  scene.directionalLights = {{glm::normalize(glm::vec3(1.0f, -1.0f, 0.0f)), glm::vec3(1.0f), 2.0f}};

  pbr::Scene opaque = scene;
  opaque.objects.back().material.alphaMode = pbr::AlphaMode::Opaque;
  pbr::FrameOptions options, plain;
  plain.shadows.mode = pbr::ShadowMode::None;
  const pbr::RenderedFrames none = pbr::renderOffscreen(shaders, scene, size, plain, 1);
  const std::vector<float> cut =
      pbr::visibilityRatio(pbr::renderOffscreen(shaders, scene, size, options, 1).hdr, none.hdr);
  const std::vector<float> full =
      pbr::visibilityRatio(pbr::renderOffscreen(shaders, opaque, size, options, 1).hdr, none.hdr);
  // Mean visibility over the two halves of the shadow's footprint, x in [1.4, 1.9] and [2.1, 2.6], |z| < 0.8 (the
  // card hides the floor up to x = 1.33 from the camera).
  auto halves = [&](const std::vector<float>& v) {
    double sum[2] = {0, 0};
    int count[2] = {0, 0};
    for (int y = 0; y < size.y; ++y) {
      for (int x = 0; x < size.x; ++x) {
        const pbr::reference::Ray ray = pbr::reference::cameraRay(scene.camera, size.x, size.y, x, y);
        const dvec3 p = ray.origin + ray.direction * (-ray.origin.y / ray.direction.y);
        const double vis = v[size_t(y) * size.x + x];
        if (std::abs(p.z) > 0.8 || vis < 0.0) continue;
        for (int h = 0; h < 2; ++h) {
          if (p.x > 1.4 + 0.7 * h && p.x < 1.9 + 0.7 * h) {
            sum[h] += vis;
            ++count[h];
          }
        }
      }
    }
    REQUIRE(count[0] > 20);
    REQUIRE(count[1] > 20);
    return std::pair<double, double>(sum[0] / count[0], sum[1] / count[1]);
  };
  const auto [cutA, cutB] = halves(cut);
  const auto [fullA, fullB] = halves(full);
  MESSAGE("masked card: " << cutA << " / " << cutB << "; opaque card: " << fullA << " / " << fullB);
  CHECK(fullA < 0.01);
  CHECK(fullB < 0.01);
  // One half of the cut-out's shadow is lit, the other as dark as the opaque card's.
  CHECK(std::min(cutA, cutB) < 0.01);
  CHECK(std::max(cutA, cutB) > 0.99);
}

TEST_CASE("shadows: lights that do not cast leave the frame as without shadows, and --shadows on makes them cast") {
  PBR_REQUIRE_GL();
  const pbr::ShaderLibrary shaders;
  const glm::ivec2 size{96, 96};
  pbr::Scene scene = boxScene({-0.3f, -1.0f, 0.2f}, 6.0f);
  scene.directionalLights[0].castsShadows = false;
  pbr::PointLight point;
  point.position = {1.5f, 2.0f, 0.5f};
  point.radius = 10.0f;
  point.luminousPower = 300.0f;
  scene.lights = {point};  // a JSON point light: castsShadows false unless asked
  pbr::FrameOptions automatic, none, on;
  none.shadows.mode = pbr::ShadowMode::None;
  on.shadows.mode = pbr::ShadowMode::On;
  const pbr::RenderedFrames a = pbr::renderOffscreen(shaders, scene, size, automatic, 1);
  const pbr::RenderedFrames n = pbr::renderOffscreen(shaders, scene, size, none, 1);
  const pbr::RenderedFrames o = pbr::renderOffscreen(shaders, scene, size, on, 1);
  CHECK(a.hdr.pixels == n.hdr.pixels);
  CHECK(a.stats.shadows.shadowedLights == 0);
  CHECK(o.stats.shadows.shadowedLights == 2);
  CHECK(o.hdr.pixels != n.hdr.pixels);
}

namespace {

// The box under a sun, a sphere, and twelve point and spot lights around them, nine of them casting.
pbr::Scene castingLightsScene() {
  pbr::Scene scene = boxScene({-0.4f, -1.0f, -0.3f}, 5.0f);
  scene.camera.position = {2.0f, 4.0f, 5.0f};
  scene.camera.up = {0.0f, 1.0f, 0.0f};
  scene.addShape(pbr::Shape::Sphere, glm::translate(glm::mat4(1.0f), {-1.5f, 1.0f, 0.5f}), grey(0.5f));
  for (int i = 0; i < 12; ++i) {
    pbr::PointLight l;
    const float a = float(i) * 0.52f;
    l.position = {2.5f * std::cos(a), 1.0f + 0.2f * float(i % 4), 2.5f * std::sin(a)};
    l.radius = 4.0f + float(i % 3);
    l.luminousPower = 150.0f;
    l.color = {0.4f + 0.05f * float(i), 0.8f, 1.0f - 0.05f * float(i)};
    l.castsShadows = i % 3 != 2;
    if (i % 2 == 1) {
      l.spot = pbr::SpotCone{glm::normalize(glm::vec3(0, 0.5f, 0) - l.position), 0.2f, 0.6f + 0.1f * float(i % 5)};
    }
    scene.lights.push_back(l);
  }
  return scene;
}

}  // namespace

TEST_CASE("shadows: clustered frames equal brute force with point, spot and directional lights casting") {
  PBR_REQUIRE_GL();
  const pbr::ShaderLibrary shaders;
  const glm::ivec2 size{128, 72};
  const pbr::Scene scene = castingLightsScene();
  for (const pbr::ShadingModel model : {pbr::ShadingModel::Pbr, pbr::ShadingModel::BlinnPhong}) {
    CAPTURE(std::string(pbr::toString(model)));
    pbr::FrameOptions clustered, brute;
    clustered.model = brute.model = model;
    brute.culling = pbr::Culling::None;
    const pbr::RenderedFrames c = pbr::renderOffscreen(shaders, scene, size, clustered, 2);
    const pbr::RenderedFrames b = pbr::renderOffscreen(shaders, scene, size, brute, 1);
    CHECK(c.stats.shadows.shadowedLights == 9);
    CHECK(c.hdr.pixels == b.hdr.pixels);
    CHECK(c.ldr.pixels == b.ldr.pixels);
  }
}

TEST_CASE("shadows: a caster drawn into all of a light's views at once shades as when drawn view by view") {
  PBR_REQUIRE_GL();
  // GBufferPass::renderDepth: instanced over runs of a light's views, each instance choosing its viewport in the
  // vertex shader (ShadowDraws::PerLight), or a draw per view. Cube faces, a spot view, a sun's cascades, a sphere
  // at several tessellations and an alpha-masked cut-out: the same depths either way.
  const pbr::ShaderLibrary shaders;
  const glm::ivec2 size{160, 90};
  pbr::Scene scene = castingLightsScene();
  pbr::Material masked = grey(0.7f);
  masked.alphaMode = pbr::AlphaMode::Mask;
  masked.baseColor = glm::vec4(0.7f, 0.7f, 0.7f, 0.3f);  // under the cut-off: casts nothing
  scene.addShape(pbr::Shape::Box, glm::translate(glm::mat4(1.0f), {1.0f, 1.5f, -1.0f}), masked);
  for (int i = 0; i < 4; ++i) {
    scene.addShape(pbr::Shape::Sphere, glm::translate(glm::mat4(1.0f), {-2.0f + 1.2f * float(i), 0.3f, 1.5f}),
                   grey(0.4f));
  }
  pbr::FrameOptions perLightOptions, perViewOptions;
  perLightOptions.shadows.draws = pbr::ShadowDraws::PerLight;
  perViewOptions.shadows.draws = pbr::ShadowDraws::PerView;
  const pbr::RenderedFrames layered = pbr::renderOffscreen(shaders, scene, size, perLightOptions, 1);
  const pbr::RenderedFrames perView = pbr::renderOffscreen(shaders, scene, size, perViewOptions, 1);
  CHECK(layered.stats.shadows.drawsPerLight);
  CHECK_FALSE(perView.stats.shadows.drawsPerLight);
  CHECK(layered.stats.shadows.viewsRendered > 12);
  CHECK(perView.stats.shadows.viewsRendered == layered.stats.shadows.viewsRendered);
  // Fewer draws: a caster seen by several of a light's views takes one.
  CHECK(layered.stats.shadows.draws < perView.stats.shadows.draws);
  CHECK(layered.hdr.pixels == perView.hdr.pixels);
  const pbr::RenderedFrames unshadowed = [&] {
    pbr::FrameOptions none;
    none.shadows.mode = pbr::ShadowMode::None;
    return pbr::renderOffscreen(shaders, scene, size, none, 1);
  }();
  CHECK(layered.hdr.pixels != unshadowed.hdr.pixels);
}

TEST_CASE("shadows: a still frame keeps its maps, and a moved light or camera draws again what it changed") {
  PBR_REQUIRE_GL();
  // ShadowFrameKey: the maps of an unchanged frame stay (no read-back, plan or draw) and shade as drawn anew; a
  // change they depend on draws again the views it changed, the others keeping their squares' depths; every frame
  // compared with a renderer that never saw the earlier frames.
  const pbr::ShaderLibrary shaders;
  const glm::ivec2 size{128, 72};
  pbr::Scene scene = castingLightsScene();
  pbr::Renderer renderer(shaders, scene, size.x, size.y);
  pbr::Profiler profiler(pbr::TimingMode::Serializing);
  pbr::FrameOptions keep, redraw;
  redraw.shadows.cache = false;
  const auto frame = [&](const pbr::FrameOptions& options) {
    pbr::ImageRgbaF hdr;
    renderer.renderFrame(options, profiler, {nullptr, &hdr});
    return hdr.pixels;
  };
  const auto fresh = [&](const pbr::Scene& s) { return pbr::renderOffscreen(shaders, s, size, redraw, 1).hdr.pixels; };
  const auto first = frame(keep);
  CHECK_FALSE(renderer.lightStats().shadows.reused);
  CHECK(renderer.lightStats().shadows.draws > 0);
  CHECK(frame(keep) == first);
  CHECK(renderer.lightStats().shadows.reused);
  CHECK(renderer.lightStats().shadows.draws == 0);
  CHECK(renderer.lightStats().shadows.viewsRendered > 0);  // the maps' views, kept
  CHECK(renderer.lightStats().shadows.viewsKept == renderer.lightStats().shadows.viewsRendered);
  CHECK(frame(redraw) == first);
  CHECK_FALSE(renderer.lightStats().shadows.reused);
  const uint32_t views = renderer.lightStats().shadows.viewsRendered;
  SUBCASE("a light moves") {
    scene.lights[0].position += glm::vec3(0.0f, 0.6f, -0.8f);
    renderer.setLights(scene.lights);
    const auto moved = frame(keep);
    const pbr::ShadowStats& s = renderer.lightStats().shadows;
    CHECK_FALSE(s.reused);
    CHECK(s.viewsKept > 0u);          // the other lights' views
    CHECK(s.viewsKept < s.viewsRendered);  // not the moved light's
    CHECK(moved != first);
    CHECK(moved == fresh(scene));
  }
  SUBCASE("the camera moves") {
    // Views whose squares stay keep their depths, the others (the cascades, and squares a light's new size on screen
    // moved) are drawn again: the frame is the one drawn anew either way.
    scene.camera.position = {-2.0f, 3.5f, 5.0f};
    renderer.setCamera(scene.camera);
    const auto turned = frame(keep);
    CHECK_FALSE(renderer.lightStats().shadows.reused);
    CHECK(renderer.lightStats().shadows.viewsKept < renderer.lightStats().shadows.viewsRendered);
    CHECK(turned == fresh(scene));
    CHECK(frame(redraw) == turned);
    CHECK(renderer.lightStats().shadows.viewsKept == 0u);
  }
  SUBCASE("an object moves") {
    // scenePosed counts a new pose: no view keeps its depths, as a caster may have moved through any.
    renderer.scenePosed({});
    CHECK(frame(keep) == first);
    CHECK(renderer.lightStats().shadows.viewsKept == 0u);
    CHECK(renderer.lightStats().shadows.viewsRendered == views);
  }
  SUBCASE("the culling changes where the occupancy comes from") {
    pbr::FrameOptions brute = keep;
    brute.culling = pbr::Culling::None;
    CHECK(frame(brute) == first);
    CHECK_FALSE(renderer.lightStats().shadows.reused);
  }
}

TEST_CASE("shadows: a spot and a point light over a sphere agree with the reference's ray-traced visibility") {
  PBR_REQUIRE_GL();
  const pbr::ShaderLibrary shaders;
  const glm::ivec2 size{160, 90};
  const pbr::Scene base = sphereOverFloor();
  const pbr::PointLight point = pointOverSphere();
  pbr::PointLight spot = point;
  spot.position = {1.8f, 3.2f, -1.0f};
  spot.spot = pbr::SpotCone{glm::normalize(glm::vec3(-0.6f, -1.0f, 0.6f)), 0.3f, 0.7f};
  // A glTF light without a range reaches kilometres: its views' near plane must still lie short of the sphere, 1.6 m
  // from it.
  pbr::PointLight far = point;
  far.radius = 2000.0f;
  for (const pbr::PointLight& light : {point, spot, far}) {
    CAPTURE(light.spot.has_value());
    CAPTURE(light.radius);
    pbr::Scene scene = base;
    scene.lights = {light};
    pbr::FrameOptions options, plain;
    plain.shadows.mode = pbr::ShadowMode::None;
    const std::vector<float> gpu = pbr::visibilityRatio(pbr::renderOffscreen(shaders, scene, size, options, 2).hdr,
                                                        pbr::renderOffscreen(shaders, scene, size, plain, 2).hdr);
    pbr::reference::ReferenceOptions referenceOptions;
    referenceOptions.shadows = pbr::ShadowMode::Auto;
    pbr::reference::ReferenceFrame expected = pbr::reference::renderReference(scene, size.x, size.y, referenceOptions);
    REQUIRE(expected.visibility.size() == gpu.size());
    // The floor's pixels (the sphere's counted as unlit, so that its outline joins the band), outside a band of 2
    // pixels around the reference's shadow edges (the penumbra of the filter and the map's texels, a few
    // millimetres here, and the rasterizer's and the ray's different rounding).
    for (size_t i = 0; i < expected.visibility.size(); ++i)
      if (expected.objectIds[i] != 0) expected.visibility[i] = -1.0f;
    const pbr::ShadowAgreement a = pbr::compareShadowState(gpu, expected, 2);
    MESSAGE(std::string(light.spot ? "spot" : "point") << ": " << a.compared - a.misclassified << " of " << a.compared
                                             << " floor pixels agree, " << a.shadowed << " shadowed in the reference");
    CHECK(a.compared > 3000);
    CHECK(a.shadowed > 100);
    CHECK(a.misclassifiedShare() <= 0.01);
    // A near plane at 1e-3 of the radius, 2 m, clipped the sphere's side facing the light: 0.65 % of them lit.
    if (light.radius > 1000.0f) CHECK(a.misclassifiedShare() <= 0.001);
  }
}

TEST_CASE("shadows: a built-in sphere cast with a coarser tessellation shadows as its full mesh does") {
  PBR_REQUIRE_GL();
  const pbr::ShaderLibrary shaders;
  const glm::ivec2 size{320, 180};
  // A 256 atlas caps the light's faces at 64 texels, about 10 cm at the sphere (radius 1, 3 m below the light), so
  // that a 16-segment sphere, within 3.8 cm of it, qualifies; the same sphere as a plain mesh (Shape::Mesh) is always
  // drawn whole.
  const glm::mat4 place = glm::scale(glm::translate(glm::mat4(1.0f), {0.0f, 1.0f, 0.0f}), glm::vec3(2.0f));
  pbr::Scene coarse;
  coarse.camera.position = {0.0f, 7.0f, 9.0f};
  coarse.camera.target = {0.0f, 0.0f, 0.0f};
  coarse.addShape(pbr::Shape::Plane, glm::scale(glm::mat4(1.0f), glm::vec3(20.0f)), grey(0.6f));
  pbr::Scene whole = coarse;
  coarse.addShape(pbr::Shape::Sphere, place, grey(0.7f));
  whole.meshes.push_back(pbr::makeSphereMesh());
  whole.objects.push_back({pbr::Shape::Mesh, int(whole.meshes.size()) - 1, place, grey(0.7f)});
  pbr::PointLight light;
  light.position = {-0.5f, 5.0f, 0.3f};
  light.radius = 8.0f;
  light.luminousPower = 2000.0f;
  light.castsShadows = true;
  coarse.lights = whole.lights = {light};
  pbr::FrameOptions options, plain;
  options.shadows.atlasSize = 256;
  plain.shadows.mode = pbr::ShadowMode::None;
  const std::vector<float> a = pbr::visibilityRatio(pbr::renderOffscreen(shaders, coarse, size, options, 2).hdr,
                                                    pbr::renderOffscreen(shaders, coarse, size, plain, 2).hdr);
  const std::vector<float> b = pbr::visibilityRatio(pbr::renderOffscreen(shaders, whole, size, options, 2).hdr,
                                                    pbr::renderOffscreen(shaders, whole, size, plain, 2).hdr);
  REQUIRE(a.size() == b.size());
  size_t compared = 0, shadowed = 0, differ = 0;
  float largest = 0.0f;
  for (size_t i = 0; i < a.size(); ++i) {
    if (a[i] < 0.0f || b[i] < 0.0f) continue;
    ++compared;
    shadowed += b[i] < 0.5f ? 1 : 0;
    differ += std::abs(a[i] - b[i]) > 0.25f ? 1 : 0;
    largest = std::max(largest, std::abs(a[i] - b[i]));
  }
  MESSAGE(compared << " pixels, " << shadowed << " shadowed, " << differ << " differ by over 0.25, largest "
                   << largest);
  CHECK(shadowed > 300);
  CHECK(largest > 0.0f);  // the coarser tessellation was drawn
  CHECK(differ <= compared / 500);
}

TEST_CASE("shadow debug view: visibility 0 exactly where the reference's shadow rays are blocked, 1 where lit") {
  PBR_REQUIRE_GL();
  const pbr::ShaderLibrary shaders;
  const glm::ivec2 size{320, 180};
  pbr::Scene scene = sphereOverFloor();
  scene.lights = {pointOverSphere()};
  pbr::FrameOptions options;
  options.debug = pbr::DebugChannel::Shadows;
  const pbr::ImageRgba8 debug = pbr::renderOffscreen(shaders, scene, size, options, 2).ldr;
  pbr::reference::ReferenceOptions referenceOptions;
  referenceOptions.shadows = pbr::ShadowMode::Auto;
  const pbr::reference::ReferenceFrame ref = pbr::reference::renderReference(scene, size.x, size.y, referenceOptions);
  REQUIRE(ref.visibility.size() == size_t(size.x) * size_t(size.y));

  // Floor pixels 2 pixels or more from any shadow edge, outside the atlas inset (top right, 9/20 of the height
  // square) and the legend (bottom left, below the upper 60 %).
  const int inset = size.y * 9 / 20;
  int shadowed = 0, lit = 0, wrongShadowed = 0, wrongLit = 0, notWhite = 0;
  for (int y = 0; y < size.y; ++y) {
    for (int x = 0; x < size.x; ++x) {
      if ((x >= size.x - inset && y < inset) || y >= size.y * 6 / 10) continue;
      const uint8_t* p = &debug.pixels[(size_t(y) * size_t(size.x) + size_t(x)) * 4];
      if (uniformAround(ref, size, x, y, 2, 0.0f)) {
        ++shadowed;
        wrongShadowed += p[0] == 0 && p[1] == 0 && p[2] == 0 ? 0 : 1;
      } else if (uniformAround(ref, size, x, y, 2, 1.0f)) {
        ++lit;
        notWhite += p[0] == 255 && p[1] == 255 && p[2] == 255 ? 0 : 1;
        wrongLit += p[0] > 127 ? 0 : 1;
      }
    }
  }
  MESSAGE(shadowed << " shadowed and " << lit << " lit floor pixels compared; " << wrongShadowed << " and "
                   << wrongLit << " differ, " << notWhite << " lit ones below 1");
  CHECK(shadowed > 1000);
  CHECK(lit > 5000);
  // Black exactly where the rays are blocked; lit wherever they are not, fully but where the filter's penumbra
  // (4 texels wide, wider than the 2-pixel band where a texel spans several pixels) reaches past the band.
  CHECK(wrongShadowed == 0);
  CHECK(wrongLit == 0);
  CHECK(notWhite <= lit / 1000);
}

TEST_CASE("shadow debug view: the atlas inset outlines the light's squares") {
  PBR_REQUIRE_GL();
  const pbr::ShaderLibrary shaders;
  const glm::ivec2 size{320, 180};
  pbr::Scene scene = sphereOverFloor();
  pbr::DirectionalLight sun;
  sun.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
  scene.directionalLights = {sun};
  pbr::FrameOptions options;
  options.debug = pbr::DebugChannel::Shadows;
  const pbr::ImageRgba8 debug = pbr::renderOffscreen(shaders, scene, size, options, 1).ldr;
  // The sun's four cascades, each a quarter of the atlas's side, lie in its lower left quarter: in the inset their
  // outlines are lines of one colour (not grey) along each square's left and lower side: 2 x 2 lines of half the
  // inset's side, and nothing else is.
  const int inset = size.y * 9 / 20, left = size.x - inset;
  int coloured = 0;
  std::vector<int> colours;
  for (int y = 0; y < inset; ++y) {
    for (int x = left; x < size.x; ++x) {
      const uint8_t* p = &debug.pixels[(size_t(y) * size_t(size.x) + size_t(x)) * 4];
      if (std::abs(int(p[0]) - int(p[1])) <= 40 && std::abs(int(p[1]) - int(p[2])) <= 40) continue;
      ++coloured;
      const int colour = p[0] << 16 | p[1] << 8 | p[2];
      if (std::find(colours.begin(), colours.end(), colour) == colours.end()) colours.push_back(colour);
      CHECK(x - left < inset / 2 + 2);  // in the left half
      CHECK(y >= inset / 2 - 2);        // in the lower half (rows from the top)
    }
  }
  CHECK(coloured >= 4 * (inset / 2) - 8);
  CHECK(coloured <= 4 * (inset / 2) + 8);
  CHECK(colours.size() == 1);
}
