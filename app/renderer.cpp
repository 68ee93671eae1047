#include "app/renderer.hpp"

#include "core/readback.hpp"

namespace pbr {

Renderer::Renderer(const ShaderLibrary& shaders, const Scene& scene, int width, int height)
    : scene_(scene),
      width_(width),
      height_(height),
      frame_(makeFrameBlock(scene.camera, width, height)),
      gbuffer_(width, height),
      gbufferPass_(shaders, scene),
      lightingPass_(shaders),
      postPass_(shaders),
      hdr_(GL_RGBA16F, width, height),
      ldr_(GL_RGBA8, width, height) {
  lights_.upload(scene.lights);
}

void Renderer::renderFrame(const FrameOptions& options, Profiler& profiler, const FrameCapture& capture) {
  profiler.beginFrame();
  {
    ScopedPass pass(profiler, "gbuffer");
    gbufferPass_.render(gbuffer_, frame_);
  }
  {
    ScopedPass pass(profiler, "lighting");
    const SurfaceTextures surface{gbuffer_.baseColor, gbuffer_.normal, gbuffer_.material, gbuffer_.depth};
    lightingPass_.renderBruteForce(surface, lights_, {options.model, options.visibility, scene_.ambient}, frame_, hdr_);
  }
  {
    ScopedPass pass(profiler, "post");
    postPass_.render(hdr_, ldr_, {options.exposure, options.model == ShadingModel::Pbr});
  }
  if (capture.ldr || capture.hdr) {
    ScopedPass pass(profiler, "readback");
    if (capture.ldr) *capture.ldr = readbackRgba8(ldr_);
    if (capture.hdr) *capture.hdr = readbackRgbaF(hdr_);
  }
  profiler.endFrame();
}

}  // namespace pbr
