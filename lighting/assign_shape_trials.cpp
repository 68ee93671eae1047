#include "lighting/assign_shape_trials.hpp"

#include <stdexcept>

namespace pbr {

namespace {

AssignShape trialShape(int trial) { return trial % 2 == 0 ? AssignShape::Invocation : AssignShape::Workgroup; }

void keepFastest(double& best, double ms) {
  if (best < 0.0 || ms < best) best = ms;
}

}  // namespace

const char* toString(AssignShape shape) {
  switch (shape) {
    case AssignShape::Automatic: return "auto";
    case AssignShape::Invocation: return "invocation";
    case AssignShape::Workgroup: return "workgroup";
  }
  return "?";
}

AssignShape parseAssignShape(const std::string& text) {
  for (const AssignShape s : {AssignShape::Automatic, AssignShape::Invocation, AssignShape::Workgroup}) {
    if (text == toString(s)) return s;
  }
  throw std::invalid_argument("unknown assignment shape '" + text + "' (expected auto, invocation or workgroup)");
}

void AssignShapeTrials::beginFrame(uint32_t lights, bool gridChanged) {
  if (lights != lights_ || gridChanged) {
    lights_ = lights;
    frame_ = 0;
    for (Trial& t : trials_) t.issued = t.read = false;
    lightPassMs_ = fillMs_ = {-1.0, -1.0};
    lightPass_.reset();
    fill_.reset();
  } else {
    ++frame_;
  }
  collect();
}

bool AssignShapeTrials::trialFrame() const {
  return !decided() && frame_ >= kFirstTrial && frame_ < kFirstTrial + kTrialFrames;
}

AssignShape AssignShapeTrials::frameShape(const std::optional<AssignShape>& chosen, bool tried) const {
  if (chosen) return *chosen;
  return trialFrame() && tried ? trialShape(frame_ - kFirstTrial) : AssignShape::Invocation;
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
  for (int i = 0; i < kTrialFrames; ++i) {
    Trial& t = trials_[static_cast<size_t>(i)];
    if (t.issued && !t.read) {
      if (queryAvailable((*t.queries)[FillEnd])) {
        GLuint64 ns[4];
        for (int q = 0; q < 4; ++q) ns[q] = queryNs((*t.queries)[q]);
        const size_t shape = trialShape(i) == AssignShape::Workgroup ? 1 : 0;
        const size_t lightPassShape = tryLightPass() ? shape : 0;
        const auto ms = [&ns](Mark begin, Mark end) { return spanMs(ns[begin], ns[end]); };
        keepFastest(lightPassMs_[lightPassShape], ms(LightPassBegin, LightPassEnd));
        keepFastest(fillMs_[shape], ms(FillBegin, FillEnd));
        t.read = true;
      }
    }
    read += t.read ? 1 : 0;
  }
  if (read < kTrialFrames) return;
  const auto faster = [](const std::array<double, 2>& ms) {
    return ms[1] < ms[0] ? AssignShape::Workgroup : AssignShape::Invocation;
  };
  lightPass_ = tryLightPass() ? faster(lightPassMs_) : AssignShape::Invocation;
  fill_ = faster(fillMs_);
}

}  // namespace pbr
