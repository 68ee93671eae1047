#pragma once
#include <memory>

#include "core/frame_block.hpp"
#include "core/image.hpp"
#include "core/profiler.hpp"
#include "core/scene.hpp"
#include "core/shader_library.hpp"
#include "core/uniform_buffer.hpp"
#include "gbuffer/gbuffer.hpp"
#include "gbuffer/gbuffer_pass.hpp"
#include "lighting/lighting_pass.hpp"
#include "post/post_pass.hpp"

namespace pbr {

struct FrameOptions {
  ShadingModel model = ShadingModel::Pbr;
  Visibility visibility = Visibility::HeightCorrelated;
  float exposure = 1.0f;
};

// Images to read back at the end of a frame (timed as the "readback" pass); null members are skipped.
struct FrameCapture {
  ImageRgba8* ldr = nullptr;
  ImageRgbaF* hdr = nullptr;  // radiance before exposure, as the lighting pass wrote it
};

// The whole frame: G-buffer -> deferred lighting (HDR RGBA16F) -> post (RGBA8), with each pass timed.
class Renderer {
 public:
  Renderer(const ShaderLibrary& shaders, const Scene& scene, int width, int height);

  void renderFrame(const FrameOptions& options, Profiler& profiler, const FrameCapture& capture = {});

  int width() const { return width_; }
  int height() const { return height_; }

 private:
  const Scene& scene_;
  int width_, height_;
  UniformBuffer<FrameBlock> frame_;
  GBuffer gbuffer_;
  GBufferPass gbufferPass_;
  LightBuffer lights_;
  LightingPass lightingPass_;
  PostPass postPass_;
  Texture hdr_;
  Texture ldr_;
};

}  // namespace pbr
