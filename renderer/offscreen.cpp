#include "renderer/offscreen.hpp"

namespace pbr {

RenderedFrames renderOffscreen(const ShaderLibrary& shaders, const Scene& scene, glm::ivec2 size,
                               const FrameOptions& options, int frames, const RendererConfig& config,
                               TimingMode timing) {
  Renderer renderer(shaders, scene, size.x, size.y, config);
  Profiler profiler(timing);
  RenderedFrames out;
  for (int i = 0; i < frames; ++i) {
    FrameCapture capture;
    if (i == frames - 1) capture = {&out.ldr, &out.hdr};
    renderer.renderFrame(options, profiler, capture);
  }
  out.timings = profiler.takeResults(true);
  out.stats = renderer.lightStats();
  return out;
}

}  // namespace pbr
