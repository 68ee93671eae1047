#include "app/accuracy/shadow_metrics.hpp"

#include <algorithm>
#include <stdexcept>

namespace pbr {

namespace {

// fp16's smallest normal is 6.1e-5: below 1e-6 the unshadowed frame holds no light to take a share of.
constexpr double kBlack = 1e-6;

// -1 not lit by the light at all (or no surface), 0 shadowed, 1 lit.
int state(float visibility) { return visibility < 0.0f ? -1 : visibility >= 0.5f ? 1 : 0; }

}  // namespace

std::vector<float> visibilityRatio(const ImageRgbaF& shadowed, const ImageRgbaF& unshadowed) {
  if (shadowed.width != unshadowed.width || shadowed.height != unshadowed.height)
    throw std::invalid_argument("visibilityRatio: the two frames differ in size");
  std::vector<float> out(size_t(unshadowed.width) * unshadowed.height, -1.0f);
  for (size_t i = 0; i < out.size(); ++i) {
    const float* s = &shadowed.pixels[i * 4];
    const float* u = &unshadowed.pixels[i * 4];
    const double base = double(u[0]) + u[1] + u[2];
    if (base > kBlack) out[i] = float((double(s[0]) + s[1] + s[2]) / base);
  }
  return out;
}

ShadowAgreement& ShadowAgreement::operator+=(const ShadowAgreement& other) {
  compared += other.compared;
  shadowed += other.shadowed;
  misclassified += other.misclassified;
  return *this;
}

ShadowAgreement compareShadowState(const std::vector<float>& visibility, const reference::ReferenceFrame& ref,
                                   int band) {
  const int w = ref.radiance.width, h = ref.radiance.height;
  if (visibility.size() != size_t(w) * h || ref.visibility.size() != visibility.size())
    throw std::invalid_argument("compareShadowState: the visibilities and the reference frame differ in size");
  ShadowAgreement a;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const size_t i = size_t(y) * w + x;
      const int expected = state(ref.visibility[i]);
      if (expected < 0 || visibility[i] < 0.0f || ref.objectIds[i] < 0 || !ref.interior(x, y)) continue;
      bool nearChange = false;
      for (int ny = std::max(y - band, 0); ny <= std::min(y + band, h - 1) && !nearChange; ++ny)
        for (int nx = std::max(x - band, 0); nx <= std::min(x + band, w - 1) && !nearChange; ++nx)
          nearChange = state(ref.visibility[size_t(ny) * w + nx]) != expected;
      if (nearChange) continue;
      ++a.compared;
      a.shadowed += expected == 0 ? 1 : 0;
      a.misclassified += state(visibility[i]) != expected ? 1 : 0;
    }
  }
  return a;
}

}  // namespace pbr
