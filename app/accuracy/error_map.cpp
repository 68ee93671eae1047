#include "app/accuracy/error_map.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <glm/common.hpp>
#include <glm/vec3.hpp>

namespace pbr {

namespace {

// Perceptually ordered dark-to-bright stops (after matplotlib's inferno), so larger errors read brighter.
glm::vec3 colourScale(double t) {
  static const glm::vec3 stops[] = {{0, 0, 4}, {87, 16, 110}, {188, 55, 84}, {249, 142, 9}, {252, 255, 164}};
  const double s = std::clamp(t, 0.0, 1.0) * 4.0;
  const int i = std::min(int(s), 3);
  return glm::mix(stops[i], stops[i + 1], float(s - i));
}

// 3x5 glyphs for decade labels, one row of 3 bits per entry, top row first.
int glyphRow(char c, int row) {
  static const int digits[10][5] = {{7, 5, 5, 5, 7}, {2, 6, 2, 2, 7}, {7, 1, 7, 4, 7}, {7, 1, 7, 1, 7},
                                    {5, 5, 7, 1, 1}, {7, 4, 7, 1, 7}, {7, 4, 7, 5, 7}, {7, 1, 1, 1, 1},
                                    {7, 5, 7, 5, 7}, {7, 5, 7, 1, 7}};
  static const int e[5] = {0, 6, 7, 4, 3}, minus[5] = {0, 0, 7, 0, 0};
  if (c >= '0' && c <= '9') return digits[c - '0'][row];
  if (c == 'e') return e[row];
  if (c == '-') return minus[row];
  return 0;
}

struct Canvas {
  ImageRgba8& image;
  void set(int x, int y, glm::vec3 c) {
    if (x < 0 || y < 0 || x >= image.width || y >= image.height) return;
    uint8_t* p = &image.pixels[(size_t(y) * image.width + x) * 4];
    p[0] = uint8_t(c.x), p[1] = uint8_t(c.y), p[2] = uint8_t(c.z), p[3] = 255;
  }
  // Text `size` pixels per glyph cell, centred on x.
  void text(const std::string& s, int cx, int y, int size) {
    const int x0 = cx - int(s.size()) * 4 * size / 2;
    for (size_t i = 0; i < s.size(); ++i)
      for (int row = 0; row < 5; ++row)
        for (int col = 0; col < 3; ++col)
          if (glyphRow(s[i], row) & (4 >> col))
            for (int dy = 0; dy < size; ++dy)
              for (int dx = 0; dx < size; ++dx) set(x0 + (int(i) * 4 + col) * size + dx, y + row * size + dy, glm::vec3(255));
  }
};

}  // namespace

ImageRgba8 errorMapImage(const std::vector<float>& values, int width, int height, double lo, double hi) {
  const int zoom = std::max(1, (320 + width - 1) / width);
  const int W = width * zoom, mapH = height * zoom, barH = 12, labelSize = 2;
  ImageRgba8 out{W, mapH + 6 + barH + 4 + 5 * labelSize + 4, {}};
  out.pixels.assign(size_t(out.width) * out.height * 4, 0);
  for (size_t i = 3; i < out.pixels.size(); i += 4) out.pixels[i] = 255;
  Canvas canvas{out};
  const double llo = std::log10(lo), lhi = std::log10(hi);
  auto position = [&](double v) { return (std::log10(std::max(v, lo)) - llo) / (lhi - llo); };
  for (int y = 0; y < mapH; ++y) {
    for (int x = 0; x < W; ++x) {
      const float v = values[size_t(y / zoom) * width + x / zoom];
      canvas.set(x, y, std::isnan(v) ? glm::vec3(96) : colourScale(position(v)));
    }
  }
  const int barY = mapH + 6, margin = 16;
  for (int x = margin; x < W - margin; ++x)
    for (int y = barY; y < barY + barH; ++y) canvas.set(x, y, colourScale(double(x - margin) / (W - 2 * margin - 1)));
  for (int decade = int(std::lround(llo)); decade <= int(std::lround(lhi)); ++decade) {
    const int x = margin + int(std::lround((decade - llo) / (lhi - llo) * (W - 2 * margin - 1)));
    for (int y = barY + barH; y < barY + barH + 3; ++y) canvas.set(x, y, glm::vec3(255));
    canvas.text(decade == 0 ? "1" : "1e" + std::to_string(decade), x, barY + barH + 4, labelSize);
  }
  return out;
}

}  // namespace pbr
