// The shadows debug channel (`--debug shadows`, lighting/shadow_debug_pass.hpp) against the CPU reference's shadow
// rays: black exactly where the reference finds the light blocked, white where it reaches, outside the penumbra.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdlib>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "reference/reference_renderer.hpp"
#include "renderer/offscreen.hpp"
#include "tests/gl_test_context.hpp"

namespace {

pbr::Material grey(float base) {
  pbr::Material m;
  m.baseColor = glm::vec3(base);
  m.roughness = 0.8f;
  return m;
}

// Whether every pixel within `band` pixels of (x, y) has the reference's state `state` (0 shadowed, 1 lit).
bool uniformAround(const pbr::reference::ReferenceFrame& ref, int width, int height, int x, int y, int band,
                   float state) {
  for (int dy = -band; dy <= band; ++dy) {
    for (int dx = -band; dx <= band; ++dx) {
      const int u = x + dx, v = y + dy;
      if (u < 0 || v < 0 || u >= width || v >= height) return false;
      const size_t i = size_t(v) * size_t(width) + size_t(u);
      if (ref.objectIds[i] != 0 || ref.visibility[i] != state) return false;
    }
  }
  return true;
}

}  // namespace

TEST_CASE("shadow debug view: visibility 0 exactly where the reference's shadow rays are blocked, 1 where lit") {
  PBR_REQUIRE_GL();
  const pbr::ShaderLibrary shaders;
  const glm::ivec2 size{320, 180};
  pbr::Scene scene;
  scene.camera.position = {0.0f, 4.0f, 6.0f};
  scene.camera.target = {0.0f, 0.5f, 0.0f};
  scene.addShape(pbr::Shape::Plane, glm::scale(glm::mat4(1.0f), glm::vec3(20.0f)), grey(0.6f));
  scene.addShape(pbr::Shape::Sphere, glm::scale(glm::translate(glm::mat4(1.0f), {0.3f, 1.2f, 0.0f}), glm::vec3(1.2f)),
                 grey(0.7f));
  pbr::PointLight point;
  point.position = {-0.8f, 3.0f, 0.6f};
  point.radius = 12.0f;
  point.luminousPower = 400.0f;
  point.castsShadows = true;
  scene.lights = {point};
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
      if (uniformAround(ref, size.x, size.y, x, y, 2, 0.0f)) {
        ++shadowed;
        wrongShadowed += p[0] == 0 && p[1] == 0 && p[2] == 0 ? 0 : 1;
      } else if (uniformAround(ref, size.x, size.y, x, y, 2, 1.0f)) {
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
  pbr::Scene scene;
  scene.camera.position = {0.0f, 4.0f, 6.0f};
  scene.camera.target = {0.0f, 0.5f, 0.0f};
  scene.addShape(pbr::Shape::Plane, glm::scale(glm::mat4(1.0f), glm::vec3(20.0f)), grey(0.6f));
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
