#include "app/accuracy/shadow_rows.hpp"

#include <stdexcept>

namespace pbr {

const char* const kDefaultShadowRows = "unshadowed,hard,pcf3x3,poisson16,pcf3x3:1024,pcf3x3:16384";

ShadowRow parseShadowRow(const std::string& item) {
  ShadowRow row;
  if (item == "unshadowed") {
    row.name = item;
    row.settings.mode = ShadowMode::None;
    return row;
  }
  const size_t colon = item.find(':');
  try {
    row.settings.filter = parseShadowFilter(item.substr(0, colon));
    if (colon != std::string::npos) {
      size_t used = 0;
      const std::string atlas = item.substr(colon + 1);
      row.settings.atlasSize = std::stoi(atlas, &used);
      if (used != atlas.size()) throw std::invalid_argument("not a number");
    }
  } catch (const std::exception&) {
    throw std::invalid_argument("shadow row '" + item + "': expected unshadowed, FILTER or FILTER:ATLAS (filters "
                                "hard, pcf3x3, poisson16)");
  }
  const int a = row.settings.atlasSize;
  if (a < kMinShadowAtlas || a > kMaxShadowAtlas || (a & (a - 1)) != 0)
    throw std::invalid_argument("shadow row '" + item + "': the atlas must be a power of two from 256 to 16384");
  row.settings.mode = ShadowMode::Auto;
  row.name = std::string("shadow-") + toString(row.settings.filter) + "-" + std::to_string(a);
  return row;
}

std::vector<ShadowRow> parseShadowRows(const std::string& list) {
  return parseRowList<ShadowRow>(list, "shadow", parseShadowRow);
}

FrameOptions shadowRowOptions(const ShadowRow& row, const Scene& scene) {
  FrameOptions options = exactVariantOptions(scene);
  options.shadows = row.settings;
  return options;
}

}  // namespace pbr
