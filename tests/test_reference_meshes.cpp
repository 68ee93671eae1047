// The reference's mesh geometry: it ray-casts the triangles the GPU rasterizes, so that the GPU frame of the
// reference's own model at full precision differs from it by float arithmetic and storage alone, and its
// difference from the exact shapes is the tessellation's error.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include <glm/gtc/matrix_transform.hpp>

#include "renderer/display_image.hpp"
#include "app/accuracy/accuracy_metrics.hpp"
#include "app/accuracy/accuracy_variants.hpp"
#include "renderer/offscreen.hpp"
#include "core/gltf_loader.hpp"
#include "reference/reference_renderer.hpp"
#include "tests/cli_util.hpp"
#include "tests/gl_test_context.hpp"
#include "tests/gltf_builder.hpp"

using namespace pbr;
using reference::Geometry;
using reference::ReferenceFrame;

namespace {

const glm::ivec2 kSize{160, 90};

glm::mat4 placed(const glm::vec3& at, const glm::vec3& scale) {
  return glm::scale(glm::translate(glm::mat4(1.0f), at), scale);
}

// A dielectric sphere of radius 1 and a metal one mirrored by a scale of -1 along x (its front faces must keep
// facing out), both tessellated as `mesh`, lit by two point lights and no ambient light: the GPU's ambient term
// is an approximation the reference does not share.
Scene sphereScene(const MeshData& mesh) {
  Scene s;
  s.name = "spheres";
  s.camera.position = {0.0f, 0.0f, 5.0f};
  s.camera.fovYDeg = 45.0f;
  s.camera.nearPlane = 0.5f;
  s.camera.farPlane = 20.0f;
  const int m =
      s.addShape(Shape::Sphere, placed({-1.1f, 0, 0}, glm::vec3(2.0f)), Material{{0.9f, 0.6f, 0.3f}, 0.4f, 0.0f}).mesh;
  s.meshes[size_t(m)] = mesh;
  s.addShape(Shape::Sphere, placed({1.1f, 0, 0}, {-2.0f, 2.0f, 2.0f}), Material{{0.95f, 0.64f, 0.54f}, 0.25f, 1.0f});
  s.lights = {{{2.0f, 2.0f, 3.0f}, 20.0f, glm::vec3(1.0f), 400.0f},
              {{-3.0f, -1.0f, 2.0f}, 20.0f, {1.0f, 0.9f, 0.8f}, 200.0f}};
  return s;
}

ReferenceFrame renderWith(const Scene& scene, Geometry geometry, glm::ivec2 size = kSize) {
  reference::ReferenceOptions options;
  options.geometry = geometry;
  return reference::renderReference(scene, size.x, size.y, options);
}

// sqrt(sum (a - b)^2 / sum b^2) over the colour channels of the pixels inside the same object in both frames.
double relativeRmse(const ReferenceFrame& a, const ReferenceFrame& b) {
  double num = 0.0, den = 0.0;
  for (int y = 0; y < b.radiance.height; ++y) {
    for (int x = 0; x < b.radiance.width; ++x) {
      const size_t i = size_t(y) * b.radiance.width + x;
      if (b.objectIds[i] < 0 || a.objectIds[i] != b.objectIds[i] || !a.interior(x, y) || !b.interior(x, y)) continue;
      for (int c = 0; c < 3; ++c) {
        const double r = b.radiance.at(x, y)[c], d = a.radiance.at(x, y)[c] - r;
        num += d * d;
        den += r * r;
      }
    }
  }
  return std::sqrt(num / den);
}

// The GPU frame of the reference's own model (exact Fresnel) at full precision: RGBA32F radiance, float G-buffer.
RenderedFrames gpuFrame(const ShaderLibrary& shaders, const Scene& scene) {
  FrameOptions options;
  options.variant = parseShadingVariant("fresnel=exact");
  options.exposure = scene.exposure;
  RendererConfig config;
  config.hdrFormat = HdrFormat::Rgba32f;
  config.gbuffer = GBufferPrecision::Float;
  return renderOffscreen(shaders, scene, kSize, options, 2, config);
}

ErrorMetrics gpuError(const ShaderLibrary& shaders, const RenderedFrames& gpu, const Scene& scene) {
  const ReferenceFrame ref = renderWith(scene, Geometry::Meshes);
  return measureError(gpu.hdr, gpu.ldr, ref, displayImage(shaders, ref.radiance, scene.exposure));
}

ErrorMetrics gpuError(const Scene& scene) {
  const ShaderLibrary shaders;
  return gpuError(shaders, gpuFrame(shaders, scene), scene);
}

}  // namespace

TEST_CASE("reference meshes: the GPU's exact model at float precision matches the mesh reference on spheres") {
  PBR_REQUIRE_GL();
  const ErrorMetrics e = gpuError(sphereScene(makeSphereMesh()));
  MESSAGE("spheres: relative RMSE " << e.relativeRmse << " over " << e.pixels << " pixels");
  CHECK(e.pixels > 2000);
  CHECK(e.relativeRmse < 1e-3);
}

TEST_CASE("reference meshes: the GPU's exact model at float precision matches the mesh reference on sphere-grid") {
  PBR_REQUIRE_GL();
  AccuracyScene grid = loadAccuracyScene("sphere-grid");
  REQUIRE(grid.scene.ambient != glm::vec3(0.0f));
  const ErrorMetrics ambient = gpuError(grid.scene);
  grid.scene.ambient = glm::vec3(0.0f);
  const ErrorMetrics direct = gpuError(grid.scene);
  // The ambient term is the BRDF's tabulated directional albedo, so ambient light adds little error of its own.
  MESSAGE("sphere-grid: relative RMSE " << direct.relativeRmse << " without ambient light, " << ambient.relativeRmse
                                        << " with the scene's");
  CHECK(direct.pixels > 1000);
  CHECK(direct.relativeRmse < 1e-3);
  CHECK(ambient.relativeRmse < 1e-3);
}

TEST_CASE("reference meshes: on fresnel-floor at every angle the float path matches the mesh reference") {
  PBR_REQUIRE_GL();
  const ShaderLibrary shaders;
  for (const char* spec : {"fresnel-floor:0", "fresnel-floor:40", "fresnel-floor:65", "fresnel-floor:80"}) {
    CAPTURE(spec);
    const AccuracyScene floor = loadAccuracyScene(spec);
    const ErrorMetrics e = gpuError(shaders, gpuFrame(shaders, floor.scene), floor.scene);
    // Float arithmetic is all that separates them: the float layout stores material channels in 32-bit floats.
    MESSAGE(floor.label << ": relative RMSE " << e.relativeRmse);
    CHECK(e.pixels > 5000);
    CHECK(e.relativeRmse < 1e-4);
  }
}

TEST_CASE("reference meshes: the geometry error against the exact shapes shrinks as the tessellation grows") {
  auto geometryError = [](int segments, int rings) {
    const Scene s = sphereScene(makeSphereMesh(segments, rings));
    return relativeRmse(renderWith(s, Geometry::Meshes), renderWith(s, Geometry::Analytic));
  };
  const double coarse = geometryError(8, 4), medium = geometryError(32, 16), fine = geometryError(128, 64);
  MESSAGE("geometry error: 8x4 " << coarse << ", 32x16 " << medium << ", 128x64 " << fine);
  CHECK(fine > 0.0);
  // Interpolated normals err by O(h^2) in the facet size h: each fourfold refinement divides the error by about 16.
  CHECK(coarse > 4.0 * medium);
  CHECK(medium > 8.0 * fine);
}

TEST_CASE("reference meshes: a plane's two triangles are the exact plane") {
  const Scene floor = loadAccuracyScene("fresnel-floor:65").scene;
  const ReferenceFrame meshes = renderWith(floor, Geometry::Meshes), exact = renderWith(floor, Geometry::Analytic);
  CHECK(meshes.objectIds == exact.objectIds);
  CHECK(relativeRmse(meshes, exact) < 1e-6);
}

TEST_CASE("reference meshes: glTF meshes render, culled and flipped like the rasterizer's double-sided faces") {
  PBR_REQUIRE_GL();
  const test::TempDir dir;
  for (const bool doubleSided : {false, true}) {
    CAPTURE(doubleSided);
    test::GltfBuilder b;
    test::QuadSpec quad;
    quad.material = b.addMaterial({{"pbrMetallicRoughness", {{"metallicFactor", 0.0}, {"roughnessFactor", 0.5}}},
                                   {"doubleSided", doubleSided}});
    // Turned 180 degrees about Y: the quad's back faces the camera.
    b.addRootNode({{"mesh", test::addQuad(b, quad)}, {"rotation", {0.0, 1.0, 0.0, 0.0}}});
    Scene scene;
    scene.name = "quad";
    scene.camera.position = {0.0f, 0.3f, 3.0f};
    scene.camera.nearPlane = 0.1f;
    scene.camera.farPlane = 20.0f;
    appendGltf(scene, b.writeGltf(dir.path(), "quad" + std::to_string(doubleSided)));
    REQUIRE(scene.objects.at(0).shape == Shape::Mesh);
    scene.lights = {{{0.5f, 0.5f, 2.0f}, 10.0f, glm::vec3(1.0f), 200.0f}};
    if (doubleSided) {
      const ErrorMetrics e = gpuError(scene);
      MESSAGE("double-sided quad from behind: relative RMSE " << e.relativeRmse);
      CHECK(e.pixels > 1000);
      CHECK(e.relativeRmse < 1e-3);
    } else {
      const ReferenceFrame culled = renderWith(scene, Geometry::Meshes);
      CHECK(std::count(culled.objectIds.begin(), culled.objectIds.end(), -1) == kSize.x * kSize.y);
    }
  }
}

TEST_CASE("reference meshes: pbr reference --geometry picks the geometry, meshes by default") {
  const test::TempDir dir;
  const test::PbrRun help = test::runPbr(dir, {"reference", "--help"});
  CHECK(help.exitCode == 0);
  CHECK(help.out.find("--geometry G            meshes (default") != std::string::npos);
  const test::PbrRun byDefault = test::runPbr(dir, {"reference", "--size", "32x18", "--hdr", dir.file("a.pfm")});
  CHECK(byDefault.exitCode == 0);
  CHECK(byDefault.out.find("(mesh geometry)") != std::string::npos);
  const test::PbrRun analytic =
      test::runPbr(dir, {"reference", "--size", "32x18", "--geometry", "analytic", "--hdr", dir.file("b.pfm")});
  CHECK(analytic.exitCode == 0);
  CHECK(analytic.out.find("(analytic geometry)") != std::string::npos);
  const test::PbrRun bad = test::runPbr(dir, {"reference", "--geometry", "nurbs", "--hdr", dir.file("x.pfm")});
  CHECK(bad.exitCode == 2);
  CHECK(test::isOneLine(bad.err));
}
