#pragma once
#include "core/gl/shader_library.hpp"
#include "core/scene/image.hpp"
#include "core/scene/tone_curve.hpp"

namespace pbr {

// A radiance image made elsewhere (the CPU reference) through the frame's own display passes: upload -> post
// (exposure, the tone curve, sRGB) -> read-back, so that it and a rendered frame reach 8 bits by the same
// transform. Needs a current GL context.
ImageRgba8 displayImage(const ShaderLibrary& shaders, const ImageRgbaF& radiance, float exposure,
                        ToneCurve curve = ToneCurve::AcesHill);

}  // namespace pbr
