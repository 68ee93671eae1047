// The automatic exposure (--exposure auto, post/exposure_meter.*): a scene lit 16 times brighter meters 4 stops
// higher and shows the same frame; the metered EV100 is the mean log2 luminance of the metered pixels, as the
// frame's own radiance says; the viewer's adaptation moves at its stated rate; a frame without light keeps the
// exposure it started from.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/scene/builtin_scenes.hpp"
#include "core/scene/exposure.hpp"
#include "renderer/renderer.hpp"
#include "tests/gl_test_context.hpp"

using namespace pbr;

namespace {

constexpr glm::ivec2 kSize{160, 90};

struct Metered {
  ImageRgba8 ldr;
  ImageRgbaF hdr;
  MeteredExposure exposure;
};

Metered renderMetered(const Scene& scene, FrameOptions options = {}) {
  const ShaderLibrary shaders;
  Renderer renderer(shaders, scene, kSize.x, kSize.y);
  Profiler profiler(TimingMode::Serializing);
  options.autoExposure = true;
  Metered m;
  renderer.renderFrame(options, profiler, {&m.ldr, &m.hdr});
  REQUIRE(renderer.meteredExposure());
  m.exposure = *renderer.meteredExposure();
  return m;
}

Scene brighter(Scene scene, float factor) {
  for (PointLight& l : scene.lights) l.luminousPower *= factor;
  for (DirectionalLight& l : scene.directionalLights) l.illuminance *= factor;
  scene.ambient *= factor;
  if (scene.environment) scene.environment->intensity *= factor;
  return scene;
}

int medianLuma(const ImageRgba8& image) {
  std::vector<int> luma;
  for (size_t i = 0; i + 3 < image.pixels.size(); i += 4) {
    luma.push_back(int(std::lround(0.2126 * image.pixels[i] + 0.7152 * image.pixels[i + 1] +
                                   0.0722 * image.pixels[i + 2])));
  }
  std::nth_element(luma.begin(), luma.begin() + std::ptrdiff_t(luma.size() / 2), luma.end());
  return luma[luma.size() / 2];
}

}  // namespace

TEST_CASE("auto exposure: a scene lit 16 times brighter meters 4 stops higher and looks the same") {
  PBR_REQUIRE_GL();
  const Scene scene = makeBuiltinScene("default");
  const Metered once = renderMetered(scene);
  const Metered sixteen = renderMetered(brighter(scene, 16.0f));
  CHECK(std::abs(double(sixteen.exposure.ev100 - once.exposure.ev100) - 4.0) <= 0.1);
  CHECK(std::abs(medianLuma(sixteen.ldr) - medianLuma(once.ldr)) < 5);
  // The exposure converged at once: applied equals metered.
  CHECK(once.exposure.ev100 == once.exposure.targetEv100);
}

TEST_CASE("auto exposure: the metered EV100 maps the mean log2 luminance between the 10th and 90th percentiles to 0.18") {
  PBR_REQUIRE_GL();
  const Metered m = renderMetered(makeBuiltinScene("default"));
  // The same statistic from the captured radiance, without bins: pixels ranked by luminance, the middle 80 % of
  // those above black averaged in log2.
  std::vector<double> logs;
  for (size_t i = 0; i + 3 < m.hdr.pixels.size(); i += 4) {
    const double l = 0.2126 * m.hdr.pixels[i] + 0.7152 * m.hdr.pixels[i + 1] + 0.0722 * m.hdr.pixels[i + 2];
    if (l >= std::exp2(-24.0)) logs.push_back(std::log2(std::min(l, std::exp2(24.0))));
  }
  REQUIRE(logs.size() > 1000);
  std::sort(logs.begin(), logs.end());
  const size_t low = logs.size() / 10, high = logs.size() * 9 / 10;
  double sum = 0.0;
  for (size_t i = low; i < high; ++i) sum += logs[i];
  const double meanLog2 = sum / double(high - low);
  // key / L = 1 / (1.2 2^EV100); the bins are an eighth of a stop wide.
  CHECK(std::abs(double(m.exposure.ev100) - (meanLog2 - std::log2(1.2 * 0.18))) <= 1.0 / 16.0);
  CHECK(std::isfinite(m.exposure.ev100));
}

TEST_CASE("auto exposure: adaptation moves 1 EV per second toward a brighter scene and 3 toward a darker one") {
  PBR_REQUIRE_GL();
  const Scene dim = makeBuiltinScene("default");
  const Scene bright = brighter(dim, 16.0f);
  const ShaderLibrary shaders;
  Profiler profiler(TimingMode::Serializing);
  FrameOptions options;
  options.autoExposure = true;
  const auto meteredAfter = [&](const Scene& first, const Scene& second) {
    Renderer renderer(shaders, first, kSize.x, kSize.y);
    renderer.renderFrame(options, profiler);
    const float start = renderer.meteredExposure()->ev100;
    // The second scene's renderer adapts from what the first metered.
    Renderer next(shaders, second, kSize.x, kSize.y);
    next.restartExposure(float(exposureFromEv100(start)));
    FrameOptions adapting = options;
    adapting.adaptSeconds = 0.5f;
    next.renderFrame(adapting, profiler);
    return next.meteredExposure()->ev100 - start;
  };
  // Brighter by 4 stops: the frame darkens by 1 EV/s, half a stop in half a second.
  CHECK(meteredAfter(dim, bright) == doctest::Approx(0.5).epsilon(1e-4));
  // Darker by 4 stops: it brightens by 3 EV/s.
  CHECK(meteredAfter(bright, dim) == doctest::Approx(-1.5).epsilon(1e-4));
}

TEST_CASE("auto exposure: a frame with no light meters nothing and keeps the exposure it started from") {
  PBR_REQUIRE_GL();
  Scene dark = makeBuiltinScene("default");
  dark = brighter(dark, 0.0f);
  dark.environment.reset();
  FrameOptions options;
  options.exposure = 0.25f;
  const Metered m = renderMetered(dark, options);
  CHECK(double(m.exposure.ev100) == doctest::Approx(ev100FromExposure(0.25)).epsilon(1e-6));
  for (size_t i = 0; i + 3 < m.ldr.pixels.size(); i += 4) REQUIRE(m.ldr.pixels[i] == 0);
}
