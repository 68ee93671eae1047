#include "app/accuracy/accuracy_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace pbr {

namespace {

// Pixels inside an object, away from its silhouette; the background is no surface to compare.
bool compared(const reference::ReferenceFrame& ref, int x, int y) {
  return ref.objectIds[size_t(y) * ref.radiance.width + x] >= 0 && ref.interior(x, y);
}

double rgbNorm(const float* p) { return std::sqrt(double(p[0]) * p[0] + double(p[1]) * p[1] + double(p[2]) * p[2]); }

}  // namespace

ErrorMetrics measureError(const ImageRgbaF& hdr, const ImageRgba8& ldr, const reference::ReferenceFrame& ref,
                          const ImageRgba8& refLdr) {
  ErrorMetrics m;
  double num = 0.0, den = 0.0, levels = 0.0;
  size_t over2 = 0;
  for (int y = 0; y < hdr.height; ++y) {
    for (int x = 0; x < hdr.width; ++x) {
      if (!compared(ref, x, y)) continue;
      ++m.pixels;
      int worst = 0;
      for (int c = 0; c < 3; ++c) {
        const double r = ref.radiance.at(x, y)[c];
        const double d = double(hdr.at(x, y)[c]) - r;
        num += d * d;
        den += r * r;
        const size_t i = (size_t(y) * hdr.width + x) * 4 + c;
        const int diff = std::abs(int(ldr.pixels[i]) - int(refLdr.pixels[i]));
        levels += diff;
        worst = std::max(worst, diff);
      }
      m.maxLevels = std::max(m.maxLevels, double(worst));
      if (worst > 2) ++over2;
    }
  }
  if (m.pixels == 0) return m;
  m.relativeRmse = den > 0.0 ? std::sqrt(num / den) : std::sqrt(num);
  m.meanLevels = levels / (3.0 * m.pixels);
  m.shareOver2 = double(over2) / m.pixels;
  return m;
}

std::vector<float> relativeErrorPerPixel(const ImageRgbaF& hdr, const reference::ReferenceFrame& ref) {
  double mean = 0.0;
  size_t n = 0;
  for (int y = 0; y < hdr.height; ++y)
    for (int x = 0; x < hdr.width; ++x)
      if (compared(ref, x, y)) mean += rgbNorm(ref.radiance.at(x, y)), ++n;
  const double floor = std::max(1e-3 * (n ? mean / n : 0.0), 1e-12);
  std::vector<float> out(size_t(hdr.width) * hdr.height, std::numeric_limits<float>::quiet_NaN());
  for (int y = 0; y < hdr.height; ++y) {
    for (int x = 0; x < hdr.width; ++x) {
      if (!compared(ref, x, y)) continue;
      const float* g = hdr.at(x, y);
      const float* r = ref.radiance.at(x, y);
      const float d[3] = {g[0] - r[0], g[1] - r[1], g[2] - r[2]};
      out[size_t(y) * hdr.width + x] = float(rgbNorm(d) / std::max(rgbNorm(r), floor));
    }
  }
  return out;
}

}  // namespace pbr
