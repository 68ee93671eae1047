#include "core/gl/frame_capture.hpp"

#include <dlfcn.h>

#include <cstddef>
#include <cstdint>

namespace pbr {

// RenderDoc's in-application API as renderdoc_app.h declares it (RENDERDOC_API_1_1_2: a struct of function
// pointers, C calling convention on Linux), up to the frame-capture calls; the entries before and between them,
// never called here, are opaque slots that keep the layout.
struct RenderDocApi {
  void (*GetAPIVersion)(int* major, int* minor, int* patch);
  void* notCalled[18];  // capture options, keys, overlay, shutdown, file paths, captures, target control, UI, window
  void (*StartFrameCapture)(void* device, void* window);  // null, null: the current context, any window
  void* IsFrameCapturing;
  uint32_t (*EndFrameCapture)(void* device, void* window);
};
static_assert(offsetof(RenderDocApi, StartFrameCapture) == 19 * sizeof(void*), "RenderDoc API layout");
static_assert(offsetof(RenderDocApi, EndFrameCapture) == 21 * sizeof(void*), "RenderDoc API layout");

namespace {

constexpr int kRenderDocApi_1_1_2 = 10102;  // eRENDERDOC_API_Version_1_1_2
using GetApiFunction = int (*)(int version, void** api);

}  // namespace

FrameCapturer::FrameCapturer() {
  // RTLD_NOLOAD: RenderDoc is present only when it injected itself; loading it here would capture nothing.
  library_ = dlopen("librenderdoc.so", RTLD_NOW | RTLD_NOLOAD);
  if (!library_) return;
  const auto getApi = reinterpret_cast<GetApiFunction>(dlsym(library_, "RENDERDOC_GetAPI"));
  void* api = nullptr;
  if (getApi && getApi(kRenderDocApi_1_1_2, &api) == 1) api_ = static_cast<RenderDocApi*>(api);
}

FrameCapturer::~FrameCapturer() {
  if (library_) dlclose(library_);
}

std::string FrameCapturer::describe(int frame) const {
  const std::string mark = "the debug group and marker '" + CapturedFrame::markName(frame) + "'";
  if (!api_) {
    return "capture: RenderDoc not found (not injected into this process): frame " + std::to_string(frame) +
           " is marked by " + mark + " only, for apitrace, Nsight or a GL debug callback";
  }
  int major = 0, minor = 0, patch = 0;
  api_->GetAPIVersion(&major, &minor, &patch);
  return "capture: RenderDoc (API " + std::to_string(major) + "." + std::to_string(minor) + "." +
         std::to_string(patch) + ") captures frame " + std::to_string(frame) + ", marked by " + mark;
}

std::string CapturedFrame::markName(int frame) { return "capture frame " + std::to_string(frame); }

CapturedFrame::CapturedFrame(const FrameCapturer& capturer, int frame) : capturer_(capturer) {
  if (capturer_.api_) capturer_.api_->StartFrameCapture(nullptr, nullptr);
  insertDebugMarker(markName(frame));
  group_.emplace(markName(frame));
}

CapturedFrame::~CapturedFrame() {
  group_.reset();
  if (capturer_.api_) capturer_.api_->EndFrameCapture(nullptr, nullptr);
}

}  // namespace pbr
