// A stand-in for RenderDoc's library, preloaded under its name (librenderdoc.so) so that `pbr render
// --capture-frame` finds it as it finds RenderDoc once injected. It answers RENDERDOC_GetAPI with the layout
// renderdoc_app.h documents for RENDERDOC_API_1_1_2, written out here on its own (entry 0 GetAPIVersion, 19
// StartFrameCapture, 21 EndFrameCapture), and reports each capture call on stderr.
#include <cstdint>
#include <cstdio>

namespace {

void reportVersion(int* major, int* minor, int* patch) {
  if (major) *major = 1;
  if (minor) *minor = 1;
  if (patch) *patch = 2;
}

void startCapture(void* device, void* window) {
  std::fprintf(stderr, "fake RenderDoc: StartFrameCapture(%s, %s)\n", device ? "device" : "null",
               window ? "window" : "null");
}

uint32_t endCapture(void* device, void* window) {
  std::fprintf(stderr, "fake RenderDoc: EndFrameCapture(%s, %s)\n", device ? "device" : "null",
               window ? "window" : "null");
  return 1;
}

struct Api {
  void (*getApiVersion)(int*, int*, int*) = reportVersion;
  void* entries1To18[18] = {};
  void (*startFrameCapture)(void*, void*) = startCapture;
  void* isFrameCapturing = nullptr;
  uint32_t (*endFrameCapture)(void*, void*) = endCapture;
} api;

}  // namespace

extern "C" __attribute__((visibility("default"))) int RENDERDOC_GetAPI(int version, void** out) {
  if (version != 10102 || !out) return 0;  // eRENDERDOC_API_Version_1_1_2
  *out = &api;
  return 1;
}
