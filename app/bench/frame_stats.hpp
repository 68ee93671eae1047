#pragma once
#include <string>
#include <vector>

#include "core/io/frame_timing.hpp"

namespace pbr {

double median(std::vector<double> values);

// Median per pass over the given frames, in the order passes first appear.
std::vector<PassTiming> medianPassTimes(const std::vector<FrameTiming>& frames);

}  // namespace pbr
