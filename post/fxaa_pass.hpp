#pragma once
#include <cstdint>
#include <memory>

#include "core/gl/gl_objects.hpp"
#include "core/gl/program_cache.hpp"
#include "post/anti_aliasing.hpp"

namespace pbr {

// Mirrors the head of shaders/post/fxaa.comp's Edges block (std430): the edge pass's indirect dispatch (workgroups
// x, y, z) and the edge pixels listed.
struct FxaaEdgesHeader {
  uint32_t groups[3];
  uint32_t listed;
};
static_assert(sizeof(FxaaEdgesHeader) == 16, "std430 uvec4");

// FXAA 3.11 (shaders/post/fxaa.comp): RGBA8 display image in (sampled bilinearly), anti-aliased RGBA8 of the same
// size out. A pass over every pixel copies those off a luma edge and lists the others, which a second pass, an
// indirect dispatch over the list, filters.
class FxaaPass {
 public:
  explicit FxaaPass(ProgramCache& programs);
  void render(const Texture& display, const Texture& out);
  // The program's defines: the pass over every pixel (false) or the one over the listed edge pixels (true).
  static ShaderDefines defines(bool edgePixels);

 private:
  ProgramCache& programs_;  // compiled on first use: frames without anti-aliasing never build it
  Sampler bilinear_;
  std::unique_ptr<Buffer> edges_;  // FxaaEdgesHeader, then a pixel each (sized for the frame)
};

}  // namespace pbr
