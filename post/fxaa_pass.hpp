#pragma once
#include <string>

#include "core/gl/gl_objects.hpp"
#include "core/gl/program_cache.hpp"

namespace pbr {

// Anti-aliasing of the display image, after tone mapping: none, or FXAA 3.11 (shaders/post/fxaa.comp). One pass,
// no lookup tables, no history: it suits headless single-frame captures. HDR captures are never filtered.
enum class AntiAliasing { None, Fxaa };
AntiAliasing parseAntiAliasing(const std::string& name);  // "none" | "fxaa"; throws std::invalid_argument
const char* toString(AntiAliasing aa);
// What the commands that write display images (PNGs, the window) use unless told otherwise.
constexpr AntiAliasing kDisplayAntiAliasing = AntiAliasing::Fxaa;

// RGBA8 display image in (sampled bilinearly), anti-aliased RGBA8 of the same size out.
class FxaaPass {
 public:
  explicit FxaaPass(ProgramCache& programs);
  void render(const Texture& display, const Texture& out);

 private:
  ProgramCache& programs_;  // compiled on first use: frames without anti-aliasing never build it
  Sampler bilinear_;
};

}  // namespace pbr
