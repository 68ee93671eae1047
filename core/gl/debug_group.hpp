#pragma once
#include <string>

namespace pbr {

// A named region of GL work for graphics debuggers and GL debug output (glPushDebugGroup in the constructor,
// glPopDebugGroup in the destructor), so that a capture reads as the pipeline's passes. Nest freely: debuggers
// show them as a tree. Costs one driver call each way (measured in README.md, Captures).
class DebugGroup {
 public:
  explicit DebugGroup(const std::string& name);
  ~DebugGroup();
  DebugGroup(const DebugGroup&) = delete;
  DebugGroup& operator=(const DebugGroup&) = delete;
};

// One application message in the GL command stream (glDebugMessageInsert, notification severity): a marker
// that tools recording the stream (apitrace, Nsight) and debug callbacks see in place.
void insertDebugMarker(const std::string& message);

}  // namespace pbr
