#pragma once
#include <cstdint>
#include <string>

#include <glm/vec4.hpp>

#include "core/scene/frame_block.hpp"
#include "debug/debug_channel.hpp"

namespace pbr {

// std140 mirror of `LegendBlock` in shaders/common/legend.glsl: the text of a debug image's legend, ASCII, 4
// characters per uint with the first in the low byte, each text at a fixed place.
struct LegendBlock {
  glm::uvec4 text[8];  // title: characters 0-63, no-data note 64-95, the bar's low end 96-111, its high end 112-127
  glm::uvec4 lengths;  // of the title, the note, the low and the high end
};
static_assert(sizeof(LegendBlock) == 9 * 16, "LegendBlock must match its std140 layout");

// What a legend says. The legend is a title alone when `low` is empty, and otherwise a colour bar from `low` to
// `high` under it; a non-empty `noData` adds a swatch of the no-data pattern saying what it marks.
struct LegendText {
  std::string title;   // at most 64 characters: what the picture shows, in what space or encoding, with units
  std::string low;     // at most 16
  std::string high;    // at most 16; empty beside a non-empty `low`: the shader draws a value only it knows
  std::string noData;  // at most 32
};

// Upper-cases the text into the block. Throws std::logic_error naming the text when one is over its length or
// holds a character the legend font lacks (it has ASCII 32 to 90: space, punctuation, digits and capitals).
LegendBlock makeLegendBlock(const LegendText& text);

// The legend of each channel: depth's ends are the frame's near and far planes (in scene units, read as metres),
// slices' the grid's first and last slice.
LegendText legendText(DebugChannel channel, const FrameBlock& frame, uint32_t slices);

}  // namespace pbr
