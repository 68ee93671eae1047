#pragma once
#include <cstddef>
#include <vector>

#include <glm/vec2.hpp>

namespace pbr {

// A square of the shadow atlas: its side (a power of two) and, once packed, its corner.
struct AtlasSquare {
  int size = 0;
  size_t view = 0;  // whose square: the caller's index
  glm::ivec2 origin{0};
};

// Places power-of-two squares without overlap in a square atlas of a power-of-two side that their areas fit: sorted
// largest first, each at the Morton-order position of the area placed before it. Every earlier square is a
// multiple of the current one's area, so that position is aligned to its size and the packing has no gaps.
void packSquares(std::vector<AtlasSquare>& squares);

}  // namespace pbr
