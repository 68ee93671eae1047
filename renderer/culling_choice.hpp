#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "core/gl/gl_objects.hpp"
#include "core/scene/shading_model.hpp"
#include "renderer/culling_decision.hpp"

namespace pbr {

// The counts a frame's prediction scales the measured times by.
struct CullingCounts {
  uint32_t lights = 0;
  uint64_t pixels = 0;
  double listLength = 0.0;  // light-index entries per occupied cluster, as the clusters last measured it (0: unknown)
};

// Chooses brute force or clustered culling per frame from times measured on this machine. Each frame times the path
// it runs (GPU timestamps around the cluster and lighting passes, read back a few frames later without waiting);
// the other path's prediction scales its last measurement by the counts: brute force costs a pair per light and
// pixel, clustered its assignment per light and a pair per listed light (pixels x list length). After a reset,
// frames run clustered until two whose assignment is settled (lists sized, assignment shapes chosen) are timed.
// Brute force is then tried on two frames in a row (the first may compile its program), and clustered run on two
// more, so that both are timed at the same GPU clocks (which rise over a GPU's first frames); each path keeps its
// fastest frame. No trial is made where even an eighth of a listed pair's cost per brute-force pair would make brute
// force the slower (a listed pair measured at 1.4-1.6x a brute-force one on helmet-grid, on llvmpipe and an H100,
// docs/performance.md) and a trial frame could take long (CullingDecision). Then each frame runs the cheaper
// prediction, keeping the path it ran while the two lie within 5 %. The path not running is timed again 8 frames
// later (its first time may have been taken while a GPU's clocks rose), then every 240 frames while predicted within
// 2x of the running one. A change of shading model, variant, shadows or frame size starts again.
class CullingChoice {
 public:
  enum Mark { ClusterBegin, ClusterEnd, LightingBegin, LightingEnd };

  // The path of this frame; `key` names what the costs per pair depend on (the model, variant, shadows, size);
  // `settled`: whether a clustered frame now would assign as later ones do (LightClusters::settled).
  Culling choose(const std::string& key, const CullingCounts& counts, bool settled);
  // A timestamp of the frame chosen last (brute-force frames have no cluster marks).
  void mark(Mark at);
  const CullingDecision& decision() const { return decision_; }
  // Whether both paths' costs are known (or brute force was ruled out without a trial), with no trial frame's
  // time still to come: later frames run as the predictions say.
  bool decided() const;

 private:
  struct Sample {
    CullingCounts counts;
    double clusterMs = 0.0, lightingMs = 0.0;
  };
  struct InFlight {
    std::unique_ptr<std::array<Query, 4>> queries;
    bool pending = false;   // issued, its times not read yet
    bool issuedEnd = false; // the frame reached its last mark
    bool clustered = false;
    bool settled = false;   // a clustered frame that may be sampled
    bool trial = false;     // a brute-force frame run to time it
    bool afterTrials = false;  // a clustered frame right after the brute-force trials
    bool retime = false;    // the path not chosen, timed again
    CullingCounts counts;
  };
  void collect();
  double predictClustered(const CullingCounts& now) const;
  double predictBruteForce(const CullingCounts& now) const;

  std::string key_;
  // What the measurements since the last change of key found and where they stand; a new key starts them afresh.
  struct Measurements {
    std::optional<Sample> clustered, bruteForce;
    int bruteForceTrials = 0;      // frames of brute force run before any was timed
    int clusteredSamples = 0;      // settled clustered frames timed
    int clusteredAfterTrials = 0;  // clustered frames run right after the brute-force trials
    bool afterTrialsTimed = false;
    int retimes = 0, sinceRetime = 0;  // times the path not chosen was timed again, frames since
    bool retimed = false;              // the first of those is back
  };
  Measurements m_;
  std::array<InFlight, 8> inFlight_;
  size_t next_ = 0;
  InFlight* current_ = nullptr;
  CullingDecision decision_;
};

}  // namespace pbr
