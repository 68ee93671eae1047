#pragma once
#include "core/gl/shader_library.hpp"
#include "ibl/cubemap.hpp"

namespace pbr {

// The levels of a prefiltered cube map, written by a compute program that reads the environment (unit 0, its
// own trilinear filtering, seamless) and writes one level (image unit 0) with the block of
// shaders/ibl/prefilter_specular.comp and prefilter_sheen.comp (binding 0): the level's face size, the samples per
// texel, the environment's level-0 face size and the level's roughness k / (levels - 1). Levels [first, levels of
// `target`) are written, one dispatch each.
void prefilterLevels(const Program& program, const Cubemap& environment, const Cubemap& target, int first,
                     int samples);

}  // namespace pbr
