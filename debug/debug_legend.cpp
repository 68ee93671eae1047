#include "debug/debug_legend.hpp"

#include <cctype>
#include <cstdio>
#include <stdexcept>

#include "debug/transparency_debug_pass.hpp"

namespace pbr {

namespace {

// Where each text starts in LegendBlock::text and how long it may be, as shaders/common/legend.glsl reads them.
struct TextField {
  uint32_t start, capacity;
};
constexpr TextField kTitle{0, 64}, kNote{64, 32}, kLow{96, 16}, kHigh{112, 16};

uint32_t put(LegendBlock& block, TextField field, const std::string& text) {
  if (text.size() > field.capacity) {
    throw std::logic_error("legend text '" + text + "' is over its " + std::to_string(field.capacity) + " characters");
  }
  for (uint32_t i = 0; i < text.size(); ++i) {
    const auto c = static_cast<unsigned char>(std::toupper(static_cast<unsigned char>(text[i])));
    if (c < 32 || c > 90) throw std::logic_error("legend text '" + text + "' holds a character the legend font lacks");
    const uint32_t at = field.start + i;
    block.text[at / 16][(at / 4) % 4] |= uint32_t(c) << (8 * (at % 4));
  }
  return static_cast<uint32_t>(text.size());
}

std::string metres(float value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g M", static_cast<double>(value));
  return text;
}

}  // namespace

LegendBlock makeLegendBlock(const LegendText& text) {
  LegendBlock block{};
  block.lengths = {put(block, kTitle, text.title), put(block, kNote, text.noData), put(block, kLow, text.low),
                   put(block, kHigh, text.high)};
  return block;
}

LegendText legendText(DebugChannel channel, const FrameBlock& frame, uint32_t slices) {
  switch (channel) {
    case DebugChannel::BaseColor: return {"base color: linear, shown sRGB-encoded", "", "", ""};
    case DebugChannel::Normal: return {"normal, world space: RGB = (XYZ + 1) / 2", "", "", ""};
    case DebugChannel::Roughness: return {"roughness (perceptual)", "0", "1", ""};
    case DebugChannel::Metalness: return {"metalness", "0", "1", ""};
    case DebugChannel::Occlusion: return {"ambient occlusion (1: none)", "0", "1", ""};
    case DebugChannel::Emission: return {"emission alone, exposed and tone-mapped as the frame", "", "", ""};
    case DebugChannel::Depth:
      return {"view depth, log scale from near to far plane", metres(frame.clip.x), metres(frame.clip.y), ""};
    case DebugChannel::Clusters: return {"lights per cluster, up to the frame's most", "0", "", ""};
    case DebugChannel::Slices:
      return {"depth slice, exponential in view depth", "0", std::to_string(slices ? slices - 1 : 0), ""};
    case DebugChannel::Efficiency:
      return {"culling efficiency: contributing / evaluated pairs", "0", "1", "no pair evaluated"};
    case DebugChannel::Shadows:
      return {"shadow visibility: light arriving / unshadowed; atlas inset", "0", "1", "no shadowed light"};
    case DebugChannel::Transparency:
      return {"blend layers per pixel in front of the opaque surface", "0", std::to_string(kMaxShownLayers) + "+",
              "no blend layer"};
  }
  return {};
}

}  // namespace pbr
