#pragma once
#include "app/viewer/pass_history.hpp"

namespace pbr {

// The frame-time graph of the overlay: one column per frame of `history`, newest on the right, each stacked from
// the bottom by its passes in the order they ran, a colour per pass; the scale a round number of ms over all but
// the slowest 2% of the frames. Then a legend: the passes of the last frames, with their median times. Draws into the
// current ImGui window, `width` x `height` pixels for the graph.
void drawPassGraph(const PassHistory& history, float width, float height);

}  // namespace pbr
