#pragma once
#include <optional>
#include <string>

#include "core/gl/debug_group.hpp"

namespace pbr {

struct RenderDocApi;

// Marks one frame for graphics debuggers. In a process RenderDoc has injected itself into (`renderdoccmd capture`
// or the RenderDoc UI's Launch), the frame is also captured through RenderDoc's in-application API, found at run
// time: nothing of RenderDoc is needed to build or to run without it. Either way the frame is a debug group
// "capture frame K" opened by a debug marker of the same text, which tools recording the GL stream (apitrace,
// Nsight) show and a GL debug callback receives.
class FrameCapturer {
 public:
  FrameCapturer();  // looks for RenderDoc among the libraries already loaded, never loads it
  ~FrameCapturer();
  FrameCapturer(const FrameCapturer&) = delete;
  FrameCapturer& operator=(const FrameCapturer&) = delete;

  bool renderDoc() const { return api_ != nullptr; }
  // One line for the log saying how frame `frame` is marked: by RenderDoc (with its API version), or, RenderDoc
  // not found, by the debug group and marker alone.
  std::string describe(int frame) const;

 private:
  friend class CapturedFrame;
  void* library_ = nullptr;
  RenderDocApi* api_ = nullptr;
};

// The GL work issued during this object's life is frame `frame`, marked as FrameCapturer says.
class CapturedFrame {
 public:
  CapturedFrame(const FrameCapturer& capturer, int frame);
  ~CapturedFrame();
  CapturedFrame(const CapturedFrame&) = delete;
  CapturedFrame& operator=(const CapturedFrame&) = delete;

  // "capture frame K": the debug group's name and the marker's text.
  static std::string markName(int frame);

 private:
  const FrameCapturer& capturer_;
  std::optional<DebugGroup> group_;
};

}  // namespace pbr
