#include "app/accuracy/reference_comparison.hpp"

#include "app/accuracy/accuracy_variants.hpp"
#include "renderer/display_image.hpp"
#include "renderer/offscreen.hpp"

namespace pbr {

ReferenceComparison::ReferenceComparison(const ShaderLibrary& shaders, const Scene& scene, glm::ivec2 size,
                                         const reference::ReferenceOptions& options, TimingMode timing,
                                         ToneCurve curve)
    : shaders_(shaders),
      scene_(scene),
      size_(size),
      curve_(curve),
      timing_(timing),
      reference_(reference::renderReference(scene, size.x, size.y, options)),
      referenceLdr_(displayImage(shaders, reference_.radiance, scene.displayExposure(), curve)) {}

ReferenceComparison::Result ReferenceComparison::compare(FrameOptions options) const {
  options.toneCurve = curve_;
  const RenderedFrames f = renderOffscreen(shaders_, scene_, size_, options, 3, exactVariantConfig(), timing_);
  return {measureError(f.hdr, f.ldr, reference_, referenceLdr_), relativeErrorPerPixel(f.hdr, reference_)};
}

}  // namespace pbr
