#pragma once
#include <string>

#include "core/scene/shading_model.hpp"

namespace pbr {

// What `--culling auto` decided for a frame, and from what.
struct CullingDecision {
  Culling ran = Culling::Clustered;
  double clusteredMs = -1.0;  // predicted cluster + lighting passes; negative before a clustered frame was timed
  double bruteForceMs = -1.0; // predicted brute-force lighting pass; negative before one was timed
  // Before any brute-force frame was timed, why none is tried (else negative): the least it could take (a pair at
  // an eighth of a listed pair's cost) already exceeds the clustered prediction; or the most a trial frame could
  // take (a pair at a listed pair's cost, the clustered lighting pass counted as pairs alone) is over the larger
  // of 4 clustered frames and 20 ms.
  double bruteForceAtLeastMs = -1.0;
  double bruteForceTrialUpToMs = -1.0;
  std::string describe() const;  // "clustered (predicted: clustered 1.20 ms, brute force 4.50 ms)"
};

}  // namespace pbr
