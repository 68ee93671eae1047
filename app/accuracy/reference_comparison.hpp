#pragma once
#include <vector>

#include <glm/vec2.hpp>

#include "app/accuracy/accuracy_metrics.hpp"
#include "core/gl/shader_library.hpp"
#include "core/io/frame_timing.hpp"
#include "reference/reference_renderer.hpp"
#include "renderer/frame_options.hpp"

namespace pbr {

// A scene's reference frame and its display image, made once, and GPU frames of the exact variant's configuration
// (exactVariantConfig) compared with it: what the shadow rows and the transparency rows share.
class ReferenceComparison {
 public:
  // `options` says how the reference renders (its shadows included); `curve` is the display transform of the 8-bit
  // images the error in levels is measured on.
  ReferenceComparison(const ShaderLibrary& shaders, const Scene& scene, glm::ivec2 size,
                      const reference::ReferenceOptions& options, TimingMode timing, ToneCurve curve);

  struct Result {
    ErrorMetrics error;                // the frame against the reference
    std::vector<float> relativeError;  // per pixel, for the error map
  };
  // The scene rendered with `options` (its tone curve the comparison's) against the reference.
  Result compare(FrameOptions options) const;

  const ShaderLibrary& shaders() const { return shaders_; }
  const Scene& scene() const { return scene_; }
  glm::ivec2 size() const { return size_; }
  TimingMode timing() const { return timing_; }

 private:
  const ShaderLibrary& shaders_;
  Scene scene_;
  glm::ivec2 size_;
  ToneCurve curve_;
  TimingMode timing_;
  reference::ReferenceFrame reference_;
  ImageRgba8 referenceLdr_;
};

}  // namespace pbr
