#include "shadows/atlas_packing.hpp"

#include <algorithm>
#include <cstdint>

namespace pbr {

namespace {

// The x and y of Morton index `m`: its even and odd bits.
glm::ivec2 mortonDecode(uint64_t m) {
  glm::ivec2 p(0);
  for (int bit = 0; bit < 31; ++bit) {
    p.x |= int((m >> (2 * bit)) & 1u) << bit;
    p.y |= int((m >> (2 * bit + 1)) & 1u) << bit;
  }
  return p;
}

}  // namespace

void packSquares(std::vector<AtlasSquare>& squares) {
  std::stable_sort(squares.begin(), squares.end(),
                   [](const AtlasSquare& a, const AtlasSquare& b) { return a.size > b.size; });
  uint64_t placed = 0;  // texels
  for (AtlasSquare& s : squares) {
    const uint64_t cell = uint64_t(s.size) * uint64_t(s.size);
    s.origin = mortonDecode(placed / cell) * s.size;
    placed += cell;
  }
}

}  // namespace pbr
