#pragma once
#include "core/gl/gl_objects.hpp"
#include "core/gl/program_cache.hpp"
#include "post/anti_aliasing.hpp"

namespace pbr {

// FXAA 3.11 (shaders/post/fxaa.comp): RGBA8 display image in (sampled bilinearly), anti-aliased RGBA8 of the same
// size out.
class FxaaPass {
 public:
  explicit FxaaPass(ProgramCache& programs);
  void render(const Texture& display, const Texture& out);

 private:
  ProgramCache& programs_;  // compiled on first use: frames without anti-aliasing never build it
  Sampler bilinear_;
};

}  // namespace pbr
