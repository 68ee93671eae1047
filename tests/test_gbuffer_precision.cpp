#include <doctest/doctest.h>

#include "renderer/display_image.hpp"
#include "app/accuracy/accuracy_metrics.hpp"
#include "app/accuracy/accuracy_variants.hpp"
#include "renderer/offscreen.hpp"
#include "reference/reference_renderer.hpp"
#include "tests/gl_test_context.hpp"

using namespace pbr;

TEST_CASE("G-buffer precision: the float layout removes the lean layout's quantisation error") {
  PBR_REQUIRE_GL();
  const ShaderLibrary shaders;
  const AccuracyScene floor = loadAccuracyScene("fresnel-floor:0");
  const glm::ivec2 size{96, 54};
  const reference::ReferenceFrame ref = reference::renderReference(floor.scene, size.x, size.y);
  FrameOptions options;
  options.variant = parseShadingVariant("fresnel=exact");
  RendererConfig config;
  config.hdrFormat = HdrFormat::Rgba32f;
  const ImageRgba8 refLdr = displayImage(shaders, ref.radiance, floor.scene.exposure);
  auto error = [&](const RendererConfig& c) {
    const RenderedFrames f = renderOffscreen(shaders, floor.scene, size, options, 1, c);
    return measureError(f.hdr, f.ldr, ref, refLdr).relativeRmse;
  };
  const double lean = error(config);
  config.gbuffer = GBufferPrecision::Float;
  const double full = error(config);
  MESSAGE("relative RMSE against the reference: lean " << lean << ", float " << full);
  // The floor's roughness 0.3 is stored as 76/255 in RG8: the GGX peak moves by about 2.6%.
  CHECK(lean > 1e-3);
  CHECK(full < 1e-3);
  CHECK(full < lean / 3.0);
}

TEST_CASE("G-buffer precision: bytes per pixel of both layouts") {
  PBR_REQUIRE_GL();
  Texture radiance("test.radiance", GL_RGBA16F, 10, 10);
  CHECK(GBuffer(10, 10, radiance).bytes() == 100 * 16);
  CHECK(GBuffer(10, 10, radiance, GBufferPrecision::Float).bytes() == 100 * 44);
  CHECK(std::string(toString(parseGBufferPrecision("float"))) == "float");
  CHECK_THROWS_AS(parseGBufferPrecision("half"), std::invalid_argument);
}
