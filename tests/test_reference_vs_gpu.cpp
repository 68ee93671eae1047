#include <doctest/doctest.h>

#include <cmath>

#include "core/builtin_scenes.hpp"
#include "reference/reference_renderer.hpp"
#include "tests/gl_test_context.hpp"
#include "tests/render_util.hpp"

using namespace pbr;

namespace {

// sqrt(sum (gpu - ref)^2 / sum ref^2) over the colour channels of the pixels inside objects.
double relativeRmse(const ImageRgbaF& gpu, const reference::ReferenceFrame& ref) {
  double num = 0.0, den = 0.0;
  for (int y = 0; y < gpu.height; ++y) {
    for (int x = 0; x < gpu.width; ++x) {
      if (!ref.interior(x, y)) continue;
      for (int c = 0; c < 3; ++c) {
        const double r = ref.radiance.at(x, y)[c];
        const double d = double(gpu.at(x, y)[c]) - r;
        num += d * d;
        den += r * r;
      }
    }
  }
  return std::sqrt(num / den);
}

double compare(const Scene& scene, Visibility visibility) {
  const glm::ivec2 size{160, 90};
  FrameOptions options;
  options.visibility = visibility;
  const ImageRgbaF gpu = test::renderScene(scene, size, options).hdr;
  const reference::ReferenceFrame ref = reference::renderReference(scene, size.x, size.y);
  return relativeRmse(gpu, ref);
}

Scene untexturedFresnelFloor(float angle) {
  SceneParams params;
  params.viewAngleDeg = angle;
  Scene s = makeBuiltinScene("fresnel-floor", params);
  s.objects[0].material.baseColorTexture = -1;
  s.objects[0].material.baseColor = glm::vec3(0.6f);
  return s;
}

}  // namespace

// The GPU path approximates the reference (Schlick instead of exact dielectric Fresnel, an approximate ambient
// term, tessellated spheres whose interpolated normals shift the smallest highlights), so these bounds are the
// measured size of those approximations plus a margin, not a claim of equality.
TEST_CASE("reference: the GPU frame stays close to the CPU reference on sphere-grid and fresnel-floor") {
  PBR_REQUIRE_GL();
  const Scene grid = makeBuiltinScene("sphere-grid");
  const double gridExact = compare(grid, Visibility::HeightCorrelated);
  const double gridHammon = compare(grid, Visibility::Hammon);
  MESSAGE("sphere-grid relative RMSE: exact visibility " << gridExact << ", Hammon " << gridHammon);
  CHECK(gridExact < 0.12);
  CHECK(gridHammon < 0.12);
  // At normal incidence Schlick equals the exact Fresnel term: a flat floor then matches closely.
  CHECK(compare(untexturedFresnelFloor(0.0f), Visibility::HeightCorrelated) < 0.02);
  for (float angle : {40.0f, 65.0f, 80.0f}) {
    const double e = compare(untexturedFresnelFloor(angle), Visibility::HeightCorrelated);
    MESSAGE("fresnel-floor at " << angle << " degrees: relative RMSE " << e);
    CHECK(e < 0.15);
  }
}
