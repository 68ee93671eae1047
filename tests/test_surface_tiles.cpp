// The lighting pass shades only the 8x8 tiles that hold a surface and gives the others their background in a pass of
// their own, or, without an environment, leaves them the G-buffer pass's clear, which is that background
// (shaders/lighting/surface_tiles.comp): every pixel ends with its value, and the tiles it counts as holding a
// surface are those where the captured frame shows one.
#include <doctest/doctest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "renderer/offscreen.hpp"
#include "tests/gl_test_context.hpp"

namespace {

// A small sphere in the middle of a 100x60 frame of sky (not a multiple of the tiles' 8 pixels), lit by one point
// light and the ambient term, so that each of its pixels is brighter than black.
pbr::Scene sphereInSky() {
  pbr::Scene scene;
  scene.camera.position = {0.0f, 0.0f, 6.0f};
  scene.camera.target = {0.0f, 0.0f, 0.0f};
  scene.ambient = glm::vec3(0.2f);
  scene.addShape(pbr::Shape::Sphere, glm::scale(glm::mat4(1.0f), glm::vec3(3.0f)), {glm::vec3(0.7f), 0.5f, 0.0f});
  pbr::PointLight light;
  light.position = {1.0f, 1.5f, 3.0f};
  light.radius = 10.0f;
  light.luminousPower = 400.0f;
  scene.lights.push_back(light);
  return scene;
}

}  // namespace

TEST_CASE("surface tiles: sky tiles show the background, surface tiles are shaded, no pixel is left unshaded") {
  PBR_REQUIRE_GL();
  const pbr::ShaderLibrary shaders;
  const glm::ivec2 size{100, 60};
  const pbr::Scene scene = sphereInSky();
  for (const pbr::Culling culling : {pbr::Culling::None, pbr::Culling::Clustered}) {
    for (const pbr::ShadingModel model : {pbr::ShadingModel::Pbr, pbr::ShadingModel::BlinnPhong}) {
      CAPTURE(std::string(pbr::toString(culling)));
      CAPTURE(std::string(pbr::toString(model)));
      pbr::FrameOptions options;
      options.culling = culling;
      options.model = model;
      options.stats = true;
      const pbr::RenderedFrames f = pbr::renderOffscreen(shaders, scene, size, options, 2);
      // The tiles where the frame shows a surface (any channel above black), counted here from the pixels.
      const int columns = (size.x + 7) / 8, rows = (size.y + 7) / 8;
      uint32_t withSurface = 0;
      int unwritten = 0;
      for (int ty = 0; ty < rows; ++ty) {
        for (int tx = 0; tx < columns; ++tx) {
          bool surface = false;
          for (int y = 8 * ty; y < std::min(8 * ty + 8, size.y); ++y) {
            for (int x = 8 * tx; x < std::min(8 * tx + 8, size.x); ++x) {
              const float* p = f.hdr.at(x, y);
              surface = surface || p[0] > 0.0f || p[1] > 0.0f || p[2] > 0.0f;
              // The G-buffer pass writes alpha 0 under a surface, which the lighting pass shades to 1; elsewhere
              // its clear is the background, alpha 1.
              unwritten += p[3] != 1.0f;
            }
          }
          withSurface += surface ? 1u : 0u;
        }
      }
      CHECK(unwritten == 0);
      CHECK(f.stats.pairs.tiles == uint32_t(columns * rows));
      CHECK(withSurface > 4u);
      CHECK(withSurface < f.stats.pairs.tiles / 2);
      CHECK(f.stats.pairs.surfaceTiles == withSurface);
    }
  }
}

TEST_CASE("surface tiles: more surface tiles than a dispatch dimension takes are shaded by a grid of workgroups") {
  PBR_REQUIRE_GL();
  const pbr::ShaderLibrary shaders;
  // 264 x 256 = 67,584 tiles, every one holding the wall: more workgroups than the 65,535 that one dimension of a
  // dispatch is sure to take (GL_MAX_COMPUTE_WORK_GROUP_COUNT's least maximum).
  const glm::ivec2 size{2112, 2048};
  pbr::Scene scene = sphereInSky();
  scene.objects.clear();
  const glm::mat4 wall = glm::rotate(glm::mat4(1.0f), glm::radians(90.0f), glm::vec3(1.0f, 0.0f, 0.0f)) *
                         glm::scale(glm::mat4(1.0f), glm::vec3(100.0f));
  scene.addShape(pbr::Shape::Plane, wall, {glm::vec3(0.7f), 0.5f, 0.0f});
  pbr::FrameOptions options;
  options.culling = pbr::Culling::None;
  options.model = pbr::ShadingModel::BlinnPhong;
  options.stats = true;
  const pbr::RenderedFrames f = pbr::renderOffscreen(shaders, scene, size, options, 1);
  const uint32_t tiles = uint32_t(size.x / 8 * (size.y / 8));
  CHECK(f.stats.pairs.surfaceTiles == tiles);
  const glm::uvec2 groups = f.stats.pairs.surfaceGroups;
  CHECK(groups.x <= 65535u);
  CHECK(groups.y <= 65535u);
  CHECK(uint64_t(groups.x) * groups.y >= tiles);
  CHECK(uint64_t(groups.x) * (groups.y - 1u) < tiles);  // no row of workgroups that lists nothing
  // Every pixel shaded: lit above black, and written by the lighting pass (the G-buffer pass leaves alpha 0).
  int unshaded = 0;
  for (int y = 0; y < size.y; ++y) {
    for (int x = 0; x < size.x; ++x) {
      const float* p = f.hdr.at(x, y);
      unshaded += p[3] != 1.0f || !(p[0] > 0.0f);
    }
  }
  CHECK(unshaded == 0);
}
