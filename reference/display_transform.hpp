#pragma once
#include <glm/vec3.hpp>
#include <glm/ext/vector_int3.hpp>

#include "core/scene/tone_curve.hpp"

namespace pbr::reference {

using glm::dvec3;

// What the renderer's post pass does to radiance on its way to an 8-bit sRGB frame, in double.

// Linear value of the 8-bit sRGB code k: base colours chosen this way survive the G-buffer's sRGB8 storage.
double srgbCodeToLinear(int k);
// The sRGB decoding of a code value c in [0,1].
double srgbCodeToLinearValue(double c);
// Exact piecewise sRGB encoding (IEC 61966-2-1) of a value in [0,1].
double srgbEncode(double linear);
// Stephen Hill's fit of the ACES RRT + ODT (sRGB primaries in and out), clamped to [0,1].
dvec3 acesHill(const dvec3& color);
// The tone curve `curve` of exposed linear radiance: display-linear values in [0,1], sRGB encoding still to come
// (the post pass's curves, shaders/post/tone_curves.glsl, each written here again from its definition).
dvec3 toneMap(ToneCurve curve, const dvec3& color);
// AgX's sigmoid on log2-encoded input in [0,1] (Blender's AgX Base: fulcrum (10 / 16.5, 0.18^(1/2.4)), slope 2.4,
// powers 1.5), exposed for the tests of its definition.
double agxSigmoid(double x);
// Exposure, the tone curve and sRGB encoding to the 8-bit code each channel shows (the reference's model is PBR).
glm::ivec3 displayCode(const dvec3& radiance, double exposure, ToneCurve curve);

}  // namespace pbr::reference
