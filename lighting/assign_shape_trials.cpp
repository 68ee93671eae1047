#include "lighting/assign_shape_trials.hpp"

namespace pbr {

namespace {

// The index of a measured shape in the trials' arrays.
size_t slot(AssignShape shape) { return static_cast<size_t>(shape) - 1; }

void keepFastest(double& best, double ms) {
  if (best < 0.0 || ms < best) best = ms;
}

// The measured shape of least time among the first `shapes`.
AssignShape fastest(const std::array<double, 3>& ms, size_t shapes) {
  size_t best = 0;
  for (size_t i = 1; i < shapes; ++i) {
    if (ms[i] >= 0.0 && ms[i] < ms[best]) best = i;
  }
  return kAssignShapes[best + 1];
}

}  // namespace

void AssignShapeTrials::beginFrame(uint32_t lights, uint32_t activeClusters, bool gridChanged) {
  if (lights != lights_ || gridChanged) {
    lights_ = lights;
    frame_ = 0;
    for (Trial& t : trials_) t.issued = t.read = false;
    lightPassMs_ = fillMs_ = {-1.0, -1.0, -1.0};
    lightPass_.reset();
    fill_.reset();
  } else {
    ++frame_;
  }
  // Decided on the first trial frame, when the first frame has measured the clusters holding a surface.
  if (frame_ == kFirstTrial) tryCluster_ = uint64_t(lights) * activeClusters <= kMaxPerClusterTests;
  collect();
}

bool AssignShapeTrials::trialFrame() const {
  return !decided() && frame_ >= kFirstTrial && frame_ < kFirstTrial + trialFrames();
}

AssignShape AssignShapeTrials::trialLightPass(int i) const {
  if (i == 1 && triesWorkgroupLightPass()) return AssignShape::Workgroup;
  if (i == 2) return AssignShape::Cluster;
  return AssignShape::Invocation;
}

AssignShape AssignShapeTrials::trialFill(int i) const {
  return i == 1 ? AssignShape::Workgroup : AssignShape::Invocation;
}

AssignShape AssignShapeTrials::lightPass() const {
  if (lightPass_) return *lightPass_;
  return trialFrame() ? trialLightPass(frame_ - kFirstTrial) : AssignShape::Invocation;
}

AssignShape AssignShapeTrials::fill() const {
  if (fill_) return *fill_;
  return trialFrame() ? trialFill(frame_ - kFirstTrial) : AssignShape::Invocation;
}

void AssignShapeTrials::mark(Mark at) {
  if (!trialFrame()) return;
  Trial& t = trials_[static_cast<size_t>(frame_ - kFirstTrial)];
  if (!t.queries) {
    t.queries = std::make_unique<std::array<Query, 4>>(
        std::array<Query, 4>{Query("clusters.trial.lightBegin"), Query("clusters.trial.lightEnd"),
                             Query("clusters.trial.fillBegin"), Query("clusters.trial.fillEnd")});
  }
  glQueryCounter((*t.queries)[at].id(), GL_TIMESTAMP);
  if (at == FillEnd) t.issued = true;
}

void AssignShapeTrials::collect() {
  if (decided()) return;
  int read = 0;
  for (int i = 0; i < trialFrames(); ++i) {
    Trial& t = trials_[static_cast<size_t>(i)];
    if (t.issued && !t.read && queryAvailable((*t.queries)[FillEnd])) {
      GLuint64 ns[4];
      for (int q = 0; q < 4; ++q) ns[q] = queryNs((*t.queries)[q]);
      const auto ms = [&ns](Mark begin, Mark end) { return spanMs(ns[begin], ns[end]); };
      keepFastest(lightPassMs_[slot(trialLightPass(i))], ms(LightPassBegin, LightPassEnd));
      keepFastest(fillMs_[slot(trialFill(i))], ms(FillBegin, FillEnd));
      t.read = true;
    }
    read += t.read ? 1 : 0;
  }
  if (read < trialFrames()) return;
  lightPass_ = fastest(lightPassMs_, 3);
  fill_ = fastest(fillMs_, 2);
}

}  // namespace pbr
