#include "renderer/culling_choice.hpp"

#include <algorithm>
#include <cmath>

namespace pbr {

namespace {

// A brute-force pair costs at least this share of a listed pair (measured: a listed pair costs 1.5-1.8x a
// brute-force one on llvmpipe, about 3x on an NVIDIA H100; docs/performance.md).
constexpr double kLeastBruteForceShare = 1.0 / 8.0;
// A brute-force trial frame may take up to this many clustered frames, or kTrialFloorMs.
constexpr double kTrialFrames = 4.0;
constexpr double kTrialFloorMs = 20.0;
// The path not running is timed again this many frames after the measurements, then every kRetimeEvery frames
// while predicted within kRetimeWithin of the running one.
constexpr int kFirstRetimeAfter = 8, kRetimeEvery = 240;
constexpr double kRetimeWithin = 2.0;
// Predictions this close keep the path the last frame ran, so that noise does not alternate them.
constexpr double kHysteresis = 0.05;

double ratio(double a, double b) { return b > 0.0 ? a / b : 1.0; }

}  // namespace

Culling CullingChoice::choose(const std::string& key, const CullingCounts& counts, bool settled) {
  if (current_ && !current_->issuedEnd) current_->pending = false;  // the last frame had no lighting pass to time
  current_ = nullptr;
  if (key != key_) {
    key_ = key;
    m_ = {};
    for (InFlight& f : inFlight_) f.pending = false;
  }
  collect();
  const Culling previous = decision_.ran;
  decision_ = CullingDecision{};
  Culling ran = Culling::Clustered;
  bool trialNow = false, retimeNow = false;
  // A frame that measures something waits for a free timing slot (results come back frames later on a GPU).
  const bool canTime = !inFlight_[next_].pending;
  if (m_.clustered) {
    decision_.clusteredMs = predictClustered(counts);
    if (m_.bruteForce) decision_.bruteForceMs = predictBruteForce(counts);
    // The second trial frame follows the first even when the first's time is back.
    if (m_.bruteForce && m_.bruteForceTrials != 1) {
      const double low = std::min(decision_.clusteredMs, decision_.bruteForceMs);
      const double high = std::max(decision_.clusteredMs, decision_.bruteForceMs);
      if (high - low <= kHysteresis * low) {
        ran = previous;
      } else {
        ran = decision_.bruteForceMs < decision_.clusteredMs ? Culling::None : Culling::Clustered;
      }
      // The path not chosen is timed again: once, a few frames after the measurements (a time taken while a GPU's
      // clocks rose would otherwise stand), then now and then while its prediction is within 2x, so that the
      // choice follows the scene.
      if (m_.afterTrialsTimed) {
        const bool runsBruteForce = ran == Culling::None;
        const double ranMs = runsBruteForce ? decision_.bruteForceMs : decision_.clusteredMs;
        const double otherMs = runsBruteForce ? decision_.clusteredMs : decision_.bruteForceMs;
        const int due = m_.retimes == 0 ? kFirstRetimeAfter : kRetimeEvery;
        if (++m_.sinceRetime >= due && canTime && (m_.retimes == 0 || otherMs <= kRetimeWithin * ranMs)) {
          ran = runsBruteForce ? Culling::Clustered : Culling::None;
          m_.sinceRetime = 0;
          ++m_.retimes;
          retimeNow = true;
        }
      }
    } else {
      // The sample's own list length is read back after it was taken: the latest stands in for it.
      const Sample& s = *m_.clustered;
      const double listLength = s.counts.listLength > 0.0 ? s.counts.listLength : counts.listLength;
      const double listed = double(s.counts.pixels) * listLength;
      // A trial that cannot take long is made; a longer one only where brute force might be the cheaper.
      if (listed > 0.0) {
        const double most = s.lightingMs / listed * double(counts.lights) * double(counts.pixels);
        const double least = most * kLeastBruteForceShare;
        if (most > std::max(kTrialFrames * decision_.clusteredMs, kTrialFloorMs)) {
          if (least > decision_.clusteredMs) {
            decision_.bruteForceAtLeastMs = least;
          } else {
            decision_.bruteForceTrialUpToMs = most;
          }
        }
      }
      // Brute force is tried on two frames in a row, once the list length says what a trial may cost and two
      // settled clustered frames have been timed.
      const bool ruledOut = decision_.bruteForceAtLeastMs >= 0.0 || decision_.bruteForceTrialUpToMs >= 0.0;
      if (listed > 0.0 && m_.clusteredSamples >= 2 && !ruledOut && m_.bruteForceTrials < 2 && canTime) {
        ran = Culling::None;
        ++m_.bruteForceTrials;
        trialNow = true;
      }
    }
    // Clustered again right after the trials, so that both paths are timed at the same clocks (a GPU's rise over
    // its first frames would otherwise favour the path timed later).
    if (!trialNow && m_.bruteForceTrials == 2 && m_.clusteredAfterTrials < 2 && canTime) {
      ran = Culling::Clustered;
      ++m_.clusteredAfterTrials;
    }
  }
  decision_.ran = ran;
  InFlight& f = inFlight_[next_];
  if (!f.pending) {
    next_ = (next_ + 1) % inFlight_.size();
    if (!f.queries) {
      f.queries = std::make_unique<std::array<Query, 4>>(
          std::array<Query, 4>{Query("culling.clusterBegin"), Query("culling.clusterEnd"),
                               Query("culling.lightingBegin"), Query("culling.lightingEnd")});
    }
    f.pending = true;
    f.issuedEnd = false;
    f.clustered = ran == Culling::Clustered;
    f.settled = settled;
    f.trial = ran == Culling::None && !m_.bruteForce;
    f.afterTrials = ran == Culling::Clustered && m_.bruteForceTrials == 2;
    f.retime = retimeNow;
    f.counts = counts;
    current_ = &f;
  }
  return ran;
}

bool CullingChoice::decided() const {
  if (!m_.clustered) return false;
  const bool trialPending = std::any_of(inFlight_.begin(), inFlight_.end(),
                                        [](const InFlight& f) { return f.pending && f.trial; });
  const bool ruledOut = decision_.bruteForceAtLeastMs >= 0.0 || decision_.bruteForceTrialUpToMs >= 0.0;
  return !trialPending && (ruledOut || (m_.bruteForce && m_.afterTrialsTimed && m_.retimed));
}

void CullingChoice::mark(Mark at) {
  if (!current_) return;
  glQueryCounter((*current_->queries)[at].id(), GL_TIMESTAMP);
  if (at == LightingEnd) current_->issuedEnd = true;
}

void CullingChoice::collect() {
  // Oldest first, so that the newest result of each path is the one kept.
  for (size_t k = 0; k < inFlight_.size(); ++k) {
    InFlight& f = inFlight_[(next_ + k) % inFlight_.size()];
    if (!f.pending || !f.issuedEnd) continue;
    if (!queryAvailable((*f.queries)[LightingEnd])) continue;
    GLuint64 ns[4] = {0, 0, 0, 0};
    for (int q = f.clustered ? 0 : 2; q < 4; ++q) ns[q] = queryNs((*f.queries)[q]);
    const auto ms = [&ns](Mark begin, Mark end) { return spanMs(ns[begin], ns[end]); };
    const Sample sample{f.counts, f.clustered ? ms(ClusterBegin, ClusterEnd) : 0.0, ms(LightingBegin, LightingEnd)};
    // While measuring, each path keeps its fastest frame (a first frame may wait on a compilation, a GPU clock
    // rising); once decided, the latest, so that the path running follows the scene.
    const bool measuring = !decided();
    const auto keep = [measuring, &sample, &f](std::optional<Sample>& slot) {
      const double total = sample.clusterMs + sample.lightingMs;
      if (!slot || !measuring || f.retime || total < slot->clusterMs + slot->lightingMs) slot = sample;
    };
    if (f.retime) m_.retimed = true;
    if (!f.clustered) {
      keep(m_.bruteForce);
    } else if (f.settled) {
      keep(m_.clustered);
      ++m_.clusteredSamples;
      if (f.afterTrials) m_.afterTrialsTimed = true;
    }
    f.pending = false;
  }
}

double CullingChoice::predictClustered(const CullingCounts& now) const {
  const Sample& s = *m_.clustered;
  const double listNow = now.listLength > 0.0 ? now.listLength : s.counts.listLength;
  const double pairs = s.counts.listLength > 0.0
                           ? ratio(double(now.pixels) * listNow, double(s.counts.pixels) * s.counts.listLength)
                           : ratio(double(now.pixels) * now.lights, double(s.counts.pixels) * s.counts.lights);
  return s.clusterMs * ratio(now.lights, s.counts.lights) + s.lightingMs * pairs;
}

double CullingChoice::predictBruteForce(const CullingCounts& now) const {
  const Sample& s = *m_.bruteForce;
  return s.lightingMs * ratio(double(now.pixels) * now.lights, double(s.counts.pixels) * s.counts.lights);
}

}  // namespace pbr
