#include "core/scene/tone_curve.hpp"

#include <iterator>
#include <stdexcept>
#include <string>

namespace pbr {

namespace {

struct CurveName {
  ToneCurve curve;
  const char* name;
  const char* define;
};

constexpr CurveName kCurves[] = {
    {ToneCurve::AcesHill, "aces-hill", "TONE_CURVE_ACES_HILL"},
    {ToneCurve::AcesNarkowicz, "aces-narkowicz", "TONE_CURVE_ACES_NARKOWICZ"},
    {ToneCurve::KhronosNeutral, "khronos-neutral", "TONE_CURVE_KHRONOS_NEUTRAL"},
    {ToneCurve::AgX, "agx", "TONE_CURVE_AGX"},
    {ToneCurve::Reinhard, "reinhard", "TONE_CURVE_REINHARD"},
    {ToneCurve::Exponential, "exponential", "TONE_CURVE_EXPONENTIAL"},
    {ToneCurve::Linear, "linear", "TONE_CURVE_LINEAR"},
};

const CurveName& entry(ToneCurve curve) {
  for (const CurveName& c : kCurves) {
    if (c.curve == curve) return c;
  }
  throw std::logic_error("tone curve without a name");
}

}  // namespace

ToneCurve parseToneCurve(const std::string& name) {
  for (const CurveName& c : kCurves) {
    if (name == c.name) return c.curve;
  }
  throw std::invalid_argument("unknown tone curve '" + name + "' (expected " + toneCurveNames() + ")");
}

const char* toString(ToneCurve curve) { return entry(curve).name; }

const char* toneCurveNames() {
  static const std::string names = [] {
    std::string text;
    const size_t n = std::size(kCurves);
    for (size_t i = 0; i < n; ++i) text += std::string(i == 0 ? "" : i + 1 == n ? " or " : ", ") + kCurves[i].name;
    return text;
  }();
  return names.c_str();
}

const char* toneCurveDefine(ToneCurve curve) { return entry(curve).define; }

}  // namespace pbr
