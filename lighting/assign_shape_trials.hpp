#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "core/gl_objects.hpp"

namespace pbr {

// How an assignment pass spreads its work over the GPU's invocations. `Invocation`: an invocation takes four lights
// (the light pass) or one slot's list (the fill), the shape for llvmpipe, whose few wide threads pay to start each
// invocation. `Workgroup`: a workgroup takes each light, sharing its tiles, and each slot, sharing its mask words,
// the shape a GPU needs where few invocations would otherwise run long loops alone (few large lights, long lists).
// `Automatic`: measured, by AssignShapeTrials.
enum class AssignShape { Automatic, Invocation, Workgroup };

// "auto", "invocation", "workgroup"; parseAssignShape throws std::invalid_argument on anything else.
const char* toString(AssignShape shape);
AssignShape parseAssignShape(const std::string& text);

// The automatic choice of each assignment pass's shape, by timing both on this machine: the same counts favour
// opposite shapes on a CPU rasterizer and on a GPU (docs/performance.md), and both shapes give the same lists, so
// the frames a trial takes are exact whichever runs. After the first frame of a light count on a grid (which sizes
// the lists and may compile programs), the next two take the invocation and then the workgroup shape, GPU
// timestamps around each pass; once both are back, read without waiting, each pass keeps the faster shape. Until
// then the invocation shape runs. The workgroup light pass is tried only up to kMaxWorkgroupLightPass lights: past
// them the invocation shape already gives a GPU over 16,384 invocations (an H100 ran it 8x faster at a million
// lights), while a workgroup per light costs llvmpipe about 3 ms per thousand lights.
class AssignShapeTrials {
 public:
  enum Mark { LightPassBegin, LightPassEnd, FillBegin, FillEnd };
  static constexpr uint32_t kMaxWorkgroupLightPass = 65536;

  // At the start of a frame's assignment: restarts the trials for a new light count or grid, and collects the
  // timestamps that have arrived.
  void beginFrame(uint32_t lights, bool gridChanged);
  AssignShape lightPass() const { return frameShape(lightPass_, tryLightPass()); }
  AssignShape fill() const { return frameShape(fill_, true); }
  // Whether this frame is a trial, and a timestamp of it.
  bool trialFrame() const;
  void mark(Mark at);

  bool decided() const { return lightPass_.has_value(); }
  // Fastest measured ms of each pass in each shape ([0] invocation, [1] workgroup); negative where not measured.
  std::array<double, 2> lightPassMs() const { return lightPassMs_; }
  std::array<double, 2> fillMs() const { return fillMs_; }

 private:
  static constexpr int kFirstTrial = 1, kTrialFrames = 2;  // frames counted from a restart
  struct Trial {
    std::unique_ptr<std::array<Query, 4>> queries;
    bool issued = false, read = false;
  };
  AssignShape frameShape(const std::optional<AssignShape>& chosen, bool tried) const;
  bool tryLightPass() const { return lights_ <= kMaxWorkgroupLightPass; }
  void collect();

  uint32_t lights_ = ~0u;
  int frame_ = 0;  // trial frames begun since the last restart
  std::array<Trial, kTrialFrames> trials_;
  std::array<double, 2> lightPassMs_{-1.0, -1.0}, fillMs_{-1.0, -1.0};
  std::optional<AssignShape> lightPass_, fill_;
};

}  // namespace pbr
