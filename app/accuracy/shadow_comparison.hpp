#pragma once
#include <cstddef>
#include <vector>

#include <glm/vec2.hpp>

#include "app/accuracy/reference_comparison.hpp"
#include "app/accuracy/shadow_rows.hpp"
#include "core/gl/shader_library.hpp"
#include "core/io/frame_timing.hpp"

namespace pbr {

// What every row is compared with, made once: the scene's shadowed reference frame, and per light that casts, the
// reference frame of that light alone (its shadow rays) and the unshadowed GPU frame of that light alone (the
// denominator of visibilityRatio). Lights alone are rendered without ambient light, whose share would blur the
// ratio.
class ShadowComparison {
 public:
  ShadowComparison(const ShaderLibrary& shaders, const Scene& scene, glm::ivec2 size,
                   const reference::ReferenceOptions& referenceOptions, TimingMode timing,
                   ToneCurve curve = ToneCurve::AcesHill);
  ShadowRowResult measure(const ShadowRow& row) const;
  size_t castingLights() const { return lights_.size(); }

 private:
  struct LightAlone {
    Scene scene;
    reference::ReferenceFrame reference;
    ImageRgbaF unshadowed;
  };
  ReferenceComparison frame_;  // the whole scene, shadowed, against its reference with shadow rays
  std::vector<LightAlone> lights_;
};

}  // namespace pbr
