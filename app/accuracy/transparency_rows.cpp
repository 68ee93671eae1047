#include "app/accuracy/transparency_rows.hpp"

#include <stdexcept>

#include "app/accuracy/frames_in_turn.hpp"
#include "app/accuracy/shadow_rows.hpp"
#include "renderer/display_image.hpp"
#include "renderer/offscreen.hpp"

namespace pbr {

const char* const kDefaultTransparencyRows = "sorted,oit,exact";

std::vector<TransparencyRow> parseTransparencyRows(const std::string& list) {
  return parseRowList<TransparencyRow>(list, "transparency", [](const std::string& item) {
    TransparencyRow row;
    try {
      row.transparency = parseTransparency(item);
    } catch (const std::invalid_argument&) {
      throw std::invalid_argument("transparency row '" + item + "': expected sorted, oit or exact");
    }
    row.name = std::string("transparency-") + toString(row.transparency);
    return row;
  });
}

FrameOptions transparencyRowOptions(const TransparencyRow& row, const Scene& scene) {
  FrameOptions options = exactVariantOptions(scene);
  options.shadows.mode = ShadowMode::None;
  options.transparency = row.transparency;
  return options;
}

TransparencyComparison::TransparencyComparison(const ShaderLibrary& shaders, const Scene& scene, glm::ivec2 size,
                                               const reference::ReferenceOptions& referenceOptions,
                                               TimingMode timing, ToneCurve curve)
    : shaders_(shaders), scene_(scene), size_(size), curve_(curve), timing_(timing) {
  reference::ReferenceOptions options = referenceOptions;
  options.shadows = ShadowMode::None;
  reference_ = reference::renderReference(scene, size.x, size.y, options);
  referenceLdr_ = displayImage(shaders, reference_.radiance, scene.displayExposure(), curve);
}

TransparencyRowResult TransparencyComparison::measure(const TransparencyRow& row) const {
  FrameOptions options = transparencyRowOptions(row, scene_);
  options.toneCurve = curve_;
  const RenderedFrames f = renderOffscreen(shaders_, scene_, size_, options, 3, exactVariantConfig(), timing_);
  return {measureError(f.hdr, f.ldr, reference_, referenceLdr_), relativeErrorPerPixel(f.hdr, reference_)};
}

std::vector<TransparencyCost> measureTransparencyCost(const ShaderLibrary& shaders, const Scene& scene,
                                                      glm::ivec2 size, const std::vector<TransparencyRow>& rows,
                                                      int rounds, TimingMode timing) {
  std::vector<FrameOptions> options;
  for (const TransparencyRow& row : rows) options.push_back(transparencyRowOptions(row, scene));
  std::vector<TransparencyCost> out;
  for (const std::vector<FrameTiming>& frames :
       timeFramesInTurn(shaders, scene, size, exactVariantConfig(), options, rounds, timing)) {
    std::vector<double> transparency, frame;
    for (const FrameTiming& f : frames) {
      transparency.push_back(f.pass("transparency"));
      frame.push_back(f.gpuMs);
    }
    out.push_back({summarizeTimes(transparency), summarizeTimes(frame)});
  }
  return out;
}

}  // namespace pbr
