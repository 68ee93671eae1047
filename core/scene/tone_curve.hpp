#pragma once
#include <string>

namespace pbr {

// The display transform's tone curve for PBR frames, after exposure and before sRGB encoding: the post pass's
// permutation (shaders/post/tone_curves.glsl) and the CPU reference's display transform
// (reference/display_transform.*). Blinn-Phong frames keep their clamp.
enum class ToneCurve { AcesHill, AcesNarkowicz, KhronosNeutral, AgX, Reinhard, Exponential, Linear };
constexpr ToneCurve kToneCurves[] = {ToneCurve::AcesHill, ToneCurve::AcesNarkowicz, ToneCurve::KhronosNeutral,
                                     ToneCurve::AgX,      ToneCurve::Reinhard,      ToneCurve::Exponential,
                                     ToneCurve::Linear};

ToneCurve parseToneCurve(const std::string& name);  // "aces-hill", ...; std::invalid_argument listing the names
const char* toString(ToneCurve curve);
const char* toneCurveNames();  // "aces-hill, aces-narkowicz, ...", for help texts
const char* toneCurveDefine(ToneCurve curve);  // TONE_CURVE_ACES_HILL, ..., the post pass's permutation

}  // namespace pbr
