#pragma once
#include <cstdint>
#include <vector>

#include "core/scene/scene.hpp"

namespace pbr {

// The order in which the light buffer stores a scene's point and spot lights: Z order (Morton 1966) of their
// positions, quantised on a cubic grid of 2^21 cells a side over the lights' bounding box, so that lights near each
// other in space sit near each other in the buffer. Light assignment then runs neighbouring lights in the lanes
// of one SIMD group (alike in the tiles and clusters they visit) and each cluster's lights fall in few words of
// its mask; the lighting pass reads a cluster's lights from few cache lines. Lights in the same cell are ordered
// by what the GPU receives of them, so the order, and with it every frame, depends only on the set of lights, not
// on the order a scene lists them. Returns, for each place in the buffer, the scene's index of the light there.
std::vector<uint32_t> lightBufferOrder(const std::vector<PointLight>& lights);

}  // namespace pbr
