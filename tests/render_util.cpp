#include "tests/render_util.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace pbr::test {

RenderedFrame renderScene(const Scene& scene, glm::ivec2 size, const FrameOptions& options, int frames,
                          const ClusterConfig& clusters) {
  const ShaderLibrary shaders;
  return renderOffscreen(shaders, scene, size, options, frames, RendererConfig{clusters});
}

double relativeRmse(const ImageRgbaF& a, const ImageRgbaF& ref) {
  double error2 = 0.0, norm2 = 0.0;
  for (size_t i = 0; i < a.pixels.size(); ++i) {
    if (i % 4 == 3) continue;
    error2 += std::pow(double(a.pixels[i]) - double(ref.pixels[i]), 2.0);
    norm2 += std::pow(double(ref.pixels[i]), 2.0);
  }
  return std::sqrt(error2 / norm2);
}

double maxRelativeDifference(const ImageRgbaF& a, const ImageRgbaF& b, double floor) {
  double worst = 0.0;
  for (size_t i = 0; i < a.pixels.size(); ++i) {
    if (i % 4 == 3) continue;
    const double d = std::abs(double(a.pixels[i]) - double(b.pixels[i])) / std::max(std::abs(double(b.pixels[i])), floor);
    worst = std::max(worst, d);
  }
  return worst;
}

int countDifferentBytes(const ImageRgba8& a, const ImageRgba8& b) {
  int n = 0;
  for (size_t i = 0; i < a.pixels.size(); ++i) n += a.pixels[i] != b.pixels[i];
  return n;
}

int maxByteDifference(const ImageRgba8& a, const ImageRgba8& b) {
  REQUIRE(a.pixels.size() == b.pixels.size());
  int worst = 0;
  for (size_t i = 0; i < a.pixels.size(); ++i) worst = std::max(worst, std::abs(a.pixels[i] - b.pixels[i]));
  return worst;
}

double meanAbsDifference(const ImageRgba8& a, const ImageRgba8& b) {
  REQUIRE(a.pixels.size() == b.pixels.size());
  double sum = 0.0;
  for (size_t i = 0; i < a.pixels.size(); ++i) {
    if (i % 4 != 3) sum += std::abs(a.pixels[i] - b.pixels[i]);
  }
  return sum / (a.pixels.size() / 4 * 3);
}

}  // namespace pbr::test
