#pragma once
#include <glm/vec2.hpp>

#include "renderer/offscreen.hpp"

namespace pbr::test {

using RenderedFrame = RenderedFrames;

// renderOffscreen with the project's shaders: `frames` frames, the last one captured, so that the clustered
// path has sized its index list from measured demand by the time it is read.
RenderedFrame renderScene(const Scene& scene, glm::ivec2 size, const FrameOptions& options, int frames = 2,
                          const ClusterConfig& clusters = {});

// Relative RMSE of `a`'s colour channels against `ref`'s: sqrt(sum (a - ref)^2 / sum ref^2), alpha left out.
double relativeRmse(const ImageRgbaF& a, const ImageRgbaF& ref);
// Largest |a - b| / max(|b|, floor) over all colour channels.
double maxRelativeDifference(const ImageRgbaF& a, const ImageRgbaF& b, double floor = 1e-3);
int countDifferentBytes(const ImageRgba8& a, const ImageRgba8& b);
// Largest |a - b| over every byte, alpha included.
int maxByteDifference(const ImageRgba8& a, const ImageRgba8& b);
// Mean |a - b| over the colour channels, alpha left out.
double meanAbsDifference(const ImageRgba8& a, const ImageRgba8& b);

}  // namespace pbr::test
