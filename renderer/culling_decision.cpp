#include "renderer/culling_decision.hpp"

#include <cstdio>

namespace pbr {

std::string CullingDecision::describe() const {
  char text[200];
  const auto ms = [](double v, const char* unknown) {
    char b[48];
    if (v < 0.0) return std::string(unknown);
    std::snprintf(b, sizeof b, "%.3f ms", v);
    return std::string(b);
  };
  std::string brute = ms(bruteForceMs, "not timed yet");
  if (bruteForceMs < 0.0 && bruteForceAtLeastMs >= 0.0) {
    brute = "at least " + ms(bruteForceAtLeastMs, "") + ", not tried";
  }
  if (bruteForceMs < 0.0 && bruteForceTrialUpToMs >= 0.0) {
    brute = "not tried: a frame could take up to " + ms(bruteForceTrialUpToMs, "");
  }
  std::snprintf(text, sizeof text, "%s (predicted: clustered %s, brute force %s)", toString(ran),
                ms(clusteredMs, "not timed yet").c_str(), brute.c_str());
  return text;
}

}  // namespace pbr
