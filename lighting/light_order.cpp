#include "lighting/light_order.hpp"

#include <algorithm>
#include <array>
#include <cstring>

#include <glm/common.hpp>

#include "lighting/gpu_lights.hpp"

namespace pbr {

namespace {

// The 21 low bits of v, spread to every third bit of a 63-bit word.
uint64_t spreadBits(uint64_t v) {
  v &= 0x1FFFFFull;
  v = (v | v << 32) & 0x001F00000000FFFFull;
  v = (v | v << 16) & 0x001F0000FF0000FFull;
  v = (v | v << 8) & 0x100F00F00F00F00Full;
  v = (v | v << 4) & 0x10C30C30C30C30C3ull;
  v = (v | v << 2) & 0x1249249249249249ull;
  return v;
}

// The light as the GPU receives it, bit for bit: equal only where the two would shade alike.
std::array<uint32_t, 12> gpuBits(const PointLight& light) {
  const GpuLight g = toGpuLight(light);
  const GpuSpotCone c = toGpuSpotCone(light);
  std::array<uint32_t, 12> bits{};
  std::memcpy(bits.data(), &g, sizeof g);
  std::memcpy(bits.data() + 8, &c, sizeof c);
  return bits;
}

struct Entry {
  uint64_t key;
  uint32_t index;
};

}  // namespace

std::vector<uint32_t> lightBufferOrder(const std::vector<PointLight>& lights) {
  glm::vec3 lo(0.0f), hi(0.0f);
  if (!lights.empty()) lo = hi = lights.front().position;
  for (const PointLight& l : lights) {
    lo = glm::min(lo, l.position);
    hi = glm::max(hi, l.position);
  }
  // In double, where no difference of floats overflows and no scale of a float extent does.
  const glm::dvec3 span = glm::dvec3(hi) - glm::dvec3(lo);
  const double extent = std::max({span.x, span.y, span.z});
  constexpr double kCells = double(1u << 21);
  const double scale = extent > 0.0 ? kCells / extent : 0.0;
  std::vector<Entry> entries(lights.size());
  for (size_t i = 0; i < lights.size(); ++i) {
    const glm::dvec3 offset = glm::dvec3(lights[i].position) - glm::dvec3(lo);
    const glm::dvec3 cell = glm::min(offset * scale, glm::dvec3(kCells - 1.0));
    entries[i] = {spreadBits(uint64_t(cell.x)) | spreadBits(uint64_t(cell.y)) << 1 | spreadBits(uint64_t(cell.z)) << 2,
                  static_cast<uint32_t>(i)};
  }
  std::sort(entries.begin(), entries.end(), [&](const Entry& x, const Entry& y) {
    if (x.key != y.key) return x.key < y.key;
    const auto bx = gpuBits(lights[x.index]), by = gpuBits(lights[y.index]);
    return bx != by ? bx < by : x.index < y.index;
  });
  std::vector<uint32_t> order(entries.size());
  for (size_t i = 0; i < entries.size(); ++i) order[i] = entries[i].index;
  return order;
}

}  // namespace pbr
