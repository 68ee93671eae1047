#include "app/viewer/overlay_graph.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace pbr {

namespace {

constexpr size_t kLegendFrames = 60;  // the legend's medians: a second at interactive rates

// Distinct hues on a dark background; a ninth pass repeats the first colour.
constexpr ImU32 kPalette[] = {
    IM_COL32(230, 159, 0, 255),  IM_COL32(86, 180, 233, 255),  IM_COL32(0, 158, 115, 255),
    IM_COL32(240, 228, 66, 255), IM_COL32(0, 114, 178, 255),   IM_COL32(213, 94, 0, 255),
    IM_COL32(204, 121, 167, 255), IM_COL32(180, 180, 180, 255),
};

ImU32 passColour(size_t index) { return kPalette[index % (sizeof kPalette / sizeof kPalette[0])]; }

// 1, 2 or 5 times a power of ten, at least `ms`.
float roundScale(float ms) {
  const float decade = std::pow(10.0f, std::floor(std::log10(std::max(ms, 1e-3f))));
  for (float step : {1.0f, 2.0f, 5.0f, 10.0f}) {
    if (step * decade >= ms) return step * decade;
  }
  return 10.0f * decade;
}

void tooltip(const PassHistory& history, const PassHistory::Frame& frame) {
  ImGui::BeginTooltip();
  ImGui::Text("%.2f ms", frame.totalMs());
  for (const auto& [index, ms] : frame.passes) {
    ImGui::TextColored(ImColor(passColour(index)), "%s %.3f ms", history.names()[index].c_str(), ms);
  }
  ImGui::EndTooltip();
}

}  // namespace

void drawPassGraph(const PassHistory& history, float width, float height) {
  const auto& frames = history.frames();
  // The scale fits all but the slowest 2% of the frames: one frame that compiled shaders would flatten the rest.
  // Those it does not fit reach the top.
  std::vector<float> totals;
  for (const PassHistory::Frame& f : frames) totals.push_back(f.totalMs());
  float typical = 0.0f;
  if (!totals.empty()) {
    const auto rank = totals.begin() + static_cast<std::ptrdiff_t>((totals.size() - 1) * 98 / 100);
    std::nth_element(totals.begin(), rank, totals.end());
    typical = *rank;
  }
  const float scaleMs = roundScale(typical);

  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const ImVec2 corner(origin.x + width, origin.y + height);
  ImGui::InvisibleButton("pass graph", ImVec2(width, height));
  const bool hovered = ImGui::IsItemHovered();
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->AddRectFilled(origin, corner, IM_COL32(20, 20, 24, 220));
  const float midY = origin.y + height * 0.5f;
  draw->AddLine(ImVec2(origin.x, midY), ImVec2(corner.x, midY), IM_COL32(255, 255, 255, 40));

  // The graph fills from the right as frames come in; a column is at least a pixel wide.
  const float column = std::max(width / static_cast<float>(PassHistory::kFrames), 1.0f);
  const size_t shown = std::min(frames.size(), static_cast<size_t>(width / column));
  const PassHistory::Frame* pointed = nullptr;
  const float mouseX = ImGui::GetIO().MousePos.x;
  for (size_t i = 0; i < shown; ++i) {
    const PassHistory::Frame& f = frames[frames.size() - shown + i];
    const float x1 = corner.x - static_cast<float>(shown - 1 - i) * column;
    const float x0 = x1 - column;
    if (hovered && mouseX >= x0 && mouseX < x1) pointed = &f;
    float y = corner.y;
    for (const auto& [index, ms] : f.passes) {
      const float top = std::max(y - ms / scaleMs * height, origin.y);
      if (top < y) draw->AddRectFilled(ImVec2(x0, top), ImVec2(x1, y), passColour(index));
      y = top;
    }
  }
  char label[32];
  std::snprintf(label, sizeof label, "%g ms", scaleMs);
  draw->AddText(ImVec2(origin.x + 3.0f, origin.y + 1.0f), IM_COL32(255, 255, 255, 200), label);
  std::snprintf(label, sizeof label, "%g", scaleMs * 0.5f);
  draw->AddText(ImVec2(origin.x + 3.0f, midY + 1.0f), IM_COL32(255, 255, 255, 140), label);
  if (pointed) tooltip(history, *pointed);

  for (size_t index = 0; index < history.names().size(); ++index) {
    if (!history.ranRecently(index, kLegendFrames)) continue;
    const ImVec2 swatch = ImGui::GetCursorScreenPos();
    const float side = ImGui::GetTextLineHeight();
    draw->AddRectFilled(ImVec2(swatch.x, swatch.y + 2.0f), ImVec2(swatch.x + side - 4.0f, swatch.y + side - 2.0f),
                        passColour(index));
    ImGui::Dummy(ImVec2(side, side));
    ImGui::SameLine();
    ImGui::Text("%-16s %7.3f ms", history.names()[index].c_str(), history.medianMs(index, kLegendFrames));
  }
}

}  // namespace pbr
