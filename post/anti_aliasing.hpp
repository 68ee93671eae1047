#pragma once
#include <string>

namespace pbr {

// Anti-aliasing of the display image, after tone mapping: none, or FXAA 3.11 (shaders/post/fxaa.comp). One frame,
// no lookup tables, no history: it suits headless single-frame captures. HDR captures are never filtered.
enum class AntiAliasing { None, Fxaa };
AntiAliasing parseAntiAliasing(const std::string& name);  // "none" | "fxaa"; throws std::invalid_argument
const char* toString(AntiAliasing aa);
// What the commands that write display images (PNGs, the window) use unless told otherwise.
constexpr AntiAliasing kDisplayAntiAliasing = AntiAliasing::Fxaa;

}  // namespace pbr
