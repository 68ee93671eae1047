#include "renderer/display_image.hpp"

#include <algorithm>
#include <vector>

#include "core/gl/profiler.hpp"
#include "core/gl/program_cache.hpp"
#include "core/gl/readback.hpp"
#include "post/post_pass.hpp"
#include "renderer/pass_list.hpp"

namespace pbr {

ImageRgba8 displayImage(const ShaderLibrary& shaders, const ImageRgbaF& radiance, float exposure, ToneCurve curve) {
  const int w = radiance.width, h = radiance.height;
  ProgramCache programs(shaders);
  PostPass post(programs);
  Texture hdr("displayImage.radiance", GL_RGBA32F, w, h);
  Texture ldr("displayImage.display", GL_RGBA8, w, h);
  ImageRgba8 out;
  using R = FrameResource;
  const PassList passes = {
      {"upload", {}, {R::Radiance}, [&] {
         // GL rows run bottom-up; images here top-down, as readback returns them.
         std::vector<float> flipped(radiance.pixels.size());
         const size_t row = size_t(w) * 4;
         for (int y = 0; y < h; ++y) {
           std::copy_n(&radiance.pixels[size_t(h - 1 - y) * row], row, &flipped[size_t(y) * row]);
         }
         glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
         glTextureSubImage2D(hdr.id(), 0, 0, 0, w, h, GL_RGBA, GL_FLOAT, flipped.data());
       }},
      {"post", {R::Radiance}, {R::Display}, [&] { post.render(hdr, ldr, {exposure, true, curve}); }},
      {"readback", {R::Display}, {R::Capture}, [&] { out = readbackRgba8(ldr); }},
  };
  checkPassList(passes);
  for (const FramePass& pass : passes) {
    const ScopedPass scope(nullptr, pass.name.c_str());  // untimed: a debug group only
    pass.run();
  }
  return out;
}

}  // namespace pbr
