#pragma once
#include <string>

#include "core/gl/gl_objects.hpp"

namespace pbr {

// Runs a precomputation that fills a size x size lookup table, one invocation per texel in 8x8 workgroups: the
// program reads `layout(std140, binding = 0) uniform { ivec4 sizes; }` (x: table size, y: samples per texel) and
// writes `layout(FORMAT, binding = 0) uniform writeonly image2D`. It runs alone, so it takes binding 0 of both.
// `label` names the table and its pass.
Texture computeSquareTable(const std::string& label, const Program& program, GLenum format, int size, int samples);

}  // namespace pbr
