// The legend of a debug image, in a dark panel at the bottom left: a title and, for a channel with a scale, a colour
// bar with its end values under it and, where the image marks pixels without data, a swatch of that pattern with
// what it means. The text is pbr::LegendBlock's (lighting/debug_legend.hpp); the including shader defines
// legendRamp(t), the bar's colour at t in [0, 1]. The legend is drawn after anti-aliasing, never filtered.
#include "../common/text.glsl"

// Mirrors pbr::LegendBlock: ASCII, 4 characters per uint, the first in the low byte.
layout(std140, binding = LEGEND_UBO) uniform LegendBlock {
  uvec4 text[8];   // title: characters 0-63, no-data note 64-95, the bar's low end 96-111, its high end 112-127
  uvec4 lengths;   // of the title, the note, the low and the high end
} legend;
const uint LEGEND_TITLE = 0u;
const uint LEGEND_NOTE = 64u;
const uint LEGEND_LOW = 96u;
const uint LEGEND_HIGH = 112u;

vec3 legendRamp(float t);

// Pixels without data (no surface, no light-pixel pair): grey checks, which no heat or grey ramp colour matches.
vec3 noDataPattern(ivec2 p) {
  return ((p.x / 4 + p.y / 4) & 1) == 0 ? vec3(0.3) : vec3(0.18);
}

// Positions in pixels with y down (the font's direction), from the image's top-left corner.
struct LegendLayout {
  int scale;                 // pixels per font pixel: 1 up to 359 rows, 2 up to 539, ...
  ivec2 panelMin, panelMax;  // the dark panel, max exclusive
  ivec2 title;
  bool bar;                  // a title alone when there is no low end
  ivec2 barOrigin, barSize;
  ivec2 low;                 // the end values under the bar; the high one is right-aligned (legendHighOrigin)
  ivec2 swatch, note;        // the no-data swatch (a square of the bar's height) and its text
};

// The point of the layout that pixel p (GL rows, bottom-up) is.
ivec2 legendPoint(ivec2 p, ivec2 size) {
  return ivec2(p.x, size.y - 1 - p.y);
}

int legendTextWidth(uint chars, int scale) {
  return max(int(chars) * GLYPH_ADVANCE - 1, 0) * scale;
}

LegendLayout legendLayout(ivec2 size) {
  LegendLayout l;
  int s = max(1, size.y / 180);
  l.scale = s;
  l.bar = legend.lengths.z > 0u;
  int left = 8 * s;
  int lastRow = size.y - 4 * s - 5 * s;  // the lowest text row's top
  l.barSize = ivec2(min(size.x / 3, 160 * s), 6 * s);
  l.barOrigin = ivec2(left, lastRow - 2 * s - l.barSize.y);
  l.low = ivec2(left, lastRow);
  l.swatch = ivec2(l.barOrigin.x + l.barSize.x + 6 * s, l.barOrigin.y);
  l.note = ivec2(l.swatch.x + l.barSize.y + 3 * s, l.barOrigin.y + s / 2);
  l.title = ivec2(left, l.bar ? l.barOrigin.y - 4 * s - 5 * s : lastRow);
  int width = legendTextWidth(legend.lengths.x, s);
  if (l.bar) width = max(width, legend.lengths.y > 0u ? l.note.x - left + legendTextWidth(legend.lengths.y, s)
                                                      : l.barSize.x);
  l.panelMin = ivec2(left - 4 * s, l.title.y - 3 * s);
  l.panelMax = ivec2(left + width + 4 * s, size.y - s);
  return l;
}

// Where a high end of `chars` characters starts, so that it ends where the bar does.
ivec2 legendHighOrigin(LegendLayout l, uint chars) {
  return ivec2(l.barOrigin.x + l.barSize.x - legendTextWidth(chars, l.scale), l.low.y);
}

uint legendChar(uint i) {
  return (legend.text[i / 16u][(i / 4u) % 4u] >> (8u * (i % 4u))) & 0xFFu;
}

// Whether point q lies on the legend text of `length` characters from `start`, drawn at `origin`.
bool legendTextPixel(uint start, uint length, ivec2 origin, int scale, ivec2 q) {
  int advance = GLYPH_ADVANCE * scale;
  int i = (q.x - origin.x) / advance;
  if (q.x < origin.x || i >= int(length)) return false;
  return glyphPixel(legendChar(start + uint(i)), origin + ivec2(i * advance, 0), scale, q);
}

// Whether q lies in the box at `origin` of `size` or on its white border, one font pixel wide; `inside` is
// q's position in the box.
bool inFramedBox(ivec2 q, ivec2 origin, ivec2 size, int scale, out ivec2 inside, out bool border) {
  inside = q - origin;
  border = any(lessThan(inside, ivec2(0))) || any(greaterThanEqual(inside, size));
  return all(greaterThanEqual(inside, ivec2(-scale))) && all(lessThan(inside, size + scale));
}

// `color` at pixel p (GL rows, bottom-up) of an image of `size`, with the legend drawn over it.
vec3 drawLegend(ivec2 p, ivec2 size, vec3 color) {
  ivec2 q = legendPoint(p, size);
  LegendLayout l = legendLayout(size);
  if (any(lessThan(q, l.panelMin)) || any(greaterThanEqual(q, l.panelMax))) return color;
  const vec3 white = vec3(1.0);
  if (legendTextPixel(LEGEND_TITLE, legend.lengths.x, l.title, l.scale, q)) return white;
  if (l.bar) {
    ivec2 inside;
    bool border;
    if (inFramedBox(q, l.barOrigin, l.barSize, l.scale, inside, border)) {
      return border ? white : legendRamp(clamp(float(inside.x) / float(l.barSize.x - 1), 0.0, 1.0));
    }
    if (legendTextPixel(LEGEND_LOW, legend.lengths.z, l.low, l.scale, q) ||
        legendTextPixel(LEGEND_HIGH, legend.lengths.w, legendHighOrigin(l, legend.lengths.w), l.scale, q)) {
      return white;
    }
    if (legend.lengths.y > 0u) {
      if (inFramedBox(q, l.swatch, ivec2(l.barSize.y), l.scale, inside, border)) {
        return border ? white : noDataPattern(p);
      }
      if (legendTextPixel(LEGEND_NOTE, legend.lengths.y, l.note, l.scale, q)) return white;
    }
  }
  return color * 0.25;  // a dark panel keeps the text legible over any picture
}
