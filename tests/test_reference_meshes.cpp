// The reference's mesh geometry: it ray-casts the triangles the GPU rasterizes, so that the GPU frame of the
// reference's own model at full precision differs from it by float arithmetic and storage alone.
#include <doctest/doctest.h>

#include <algorithm>
#include <string>

#include "renderer/display_image.hpp"
#include "app/accuracy/accuracy_metrics.hpp"
#include "app/accuracy/accuracy_variants.hpp"
#include "renderer/offscreen.hpp"
#include "core/scene/gltf_loader.hpp"
#include "reference/reference_renderer.hpp"
#include "tests/cli_util.hpp"
#include "tests/gl_test_context.hpp"
#include "tests/gltf_builder.hpp"
#include "tests/reference_spheres.hpp"

using namespace pbr;
using reference::Geometry;
using reference::ReferenceFrame;
using test::renderWith;
using test::sphereScene;

namespace {

// The GPU frame of the reference's own model (exact Fresnel) at full precision: RGBA32F radiance, float G-buffer.
RenderedFrames gpuFrame(const ShaderLibrary& shaders, const Scene& scene) {
  FrameOptions options;
  options.variant = parseShadingVariant("fresnel=exact");
  options.exposure = scene.exposure;
  RendererConfig config;
  config.hdrFormat = HdrFormat::Rgba32f;
  config.gbuffer = GBufferPrecision::Float;
  return renderOffscreen(shaders, scene, test::kReferenceSize, options, 2, config);
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
      CHECK(std::count(culled.objectIds.begin(), culled.objectIds.end(), -1) ==
            test::kReferenceSize.x * test::kReferenceSize.y);
    }
  }
}
