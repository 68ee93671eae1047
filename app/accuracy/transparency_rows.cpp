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

namespace {

reference::ReferenceOptions withoutShadows(reference::ReferenceOptions options) {
  options.shadows = ShadowMode::None;
  return options;
}

}  // namespace

TransparencyComparison::TransparencyComparison(const ShaderLibrary& shaders, const Scene& scene, glm::ivec2 size,
                                               const reference::ReferenceOptions& referenceOptions,
                                               TimingMode timing, ToneCurve curve)
    : frame_(shaders, scene, size, withoutShadows(referenceOptions), timing, curve) {}

TransparencyRowResult TransparencyComparison::measure(const TransparencyRow& row) const {
  ReferenceComparison::Result r = frame_.compare(transparencyRowOptions(row, frame_.scene()));
  return {r.error, std::move(r.relativeError)};
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
