#include <doctest/doctest.h>

#include <cmath>

#include "app/accuracy_variants.hpp"
#include "app/offscreen.hpp"
#include "reference/reference_renderer.hpp"
#include "tests/gl_test_context.hpp"

using namespace pbr;

namespace {

// sqrt(sum (gpu - ref)^2 / sum ref^2) over the colour channels of pixels inside objects.
double relativeRmse(const ImageRgbaF& gpu, const reference::ReferenceFrame& ref) {
  double num = 0.0, den = 0.0;
  for (int y = 0; y < gpu.height; ++y) {
    for (int x = 0; x < gpu.width; ++x) {
      if (!ref.interior(x, y) || ref.objectIds[size_t(y) * gpu.width + x] < 0) continue;
      for (int c = 0; c < 3; ++c) {
        const double d = double(gpu.at(x, y)[c]) - ref.radiance.at(x, y)[c];
        num += d * d;
        den += double(ref.radiance.at(x, y)[c]) * ref.radiance.at(x, y)[c];
      }
    }
  }
  return std::sqrt(num / den);
}

}  // namespace

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
  const double lean = relativeRmse(renderOffscreen(shaders, floor.scene, size, options, 1, config).hdr, ref);
  config.gbuffer = GBufferPrecision::Float;
  const double full = relativeRmse(renderOffscreen(shaders, floor.scene, size, options, 1, config).hdr, ref);
  MESSAGE("relative RMSE against the reference: lean " << lean << ", float " << full);
  // The floor's roughness 0.3 is stored as 76/255 in RG8: the GGX peak moves by about 2.6%.
  CHECK(lean > 1e-3);
  CHECK(full < 1e-3);
  CHECK(full < lean / 3.0);
}

TEST_CASE("G-buffer precision: bytes per pixel of both layouts") {
  PBR_REQUIRE_GL();
  Texture radiance(GL_RGBA16F, 10, 10);
  CHECK(GBuffer(10, 10, radiance).bytes() == 100 * 16);
  CHECK(GBuffer(10, 10, radiance, GBufferPrecision::Float).bytes() == 100 * 28);
  CHECK(std::string(toString(parseGBufferPrecision("float"))) == "float");
  CHECK_THROWS_AS(parseGBufferPrecision("half"), std::invalid_argument);
}
