#pragma once
#include <glm/vec3.hpp>

namespace pbr::reference {

using glm::dvec3;

// What the renderer's post pass does to radiance on its way to an 8-bit sRGB frame, in double.

// Linear value of the 8-bit sRGB code k: base colours chosen this way survive the G-buffer's sRGB8 storage.
double srgbCodeToLinear(int k);
// Exact piecewise sRGB encoding (IEC 61966-2-1) of a value in [0,1].
double srgbEncode(double linear);
// Stephen Hill's fit of the ACES RRT + ODT (sRGB primaries in and out), clamped to [0,1].
dvec3 acesHill(const dvec3& color);

}  // namespace pbr::reference
