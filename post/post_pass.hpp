#pragma once
#include <array>
#include <iterator>

#include <glm/vec2.hpp>

#include "core/gl/program_cache.hpp"
#include "core/gl/uniform_buffer.hpp"
#include "core/scene/tone_curve.hpp"
#include "post/exposure_meter.hpp"
#include "post/post_bindings.hpp"

namespace pbr {

// std140 mirror of `PostBlock` in shaders/post/post.comp.
struct PostBlock {
  float exposure;
  unsigned toneMap;
  glm::uvec2 size;
};
static_assert(sizeof(PostBlock) == 16, "PostBlock must match its std140 layout");

struct PostSettings {
  float exposure = 1.0f;
  bool toneMap = true;  // false for LDR frames: clamp + sRGB only
  ToneCurve curve = ToneCurve::AcesHill;
  const ExposureMeter* meter = nullptr;  // automatic exposure: the meter's exposure replaces `exposure`
};

// HDR RGBA16F in, display-referred RGBA8 (sRGB-encoded values) out.
// A permutation per tone curve and exposure source, each compiled when a frame first asks for it.
class PostPass {
 public:
  explicit PostPass(ProgramCache& programs) : programs_(programs) { program(ToneCurve::AcesHill, false); }
  void render(const Texture& hdr, const Texture& ldr, const PostSettings& settings);
  // The defines of a permutation: the curve's TONE_CURVE_* define 1, the others 0; AUTO_EXPOSURE 1 when the
  // exposure comes from the meter.
  static ShaderDefines permutation(ToneCurve curve, bool autoExposure);

 private:
  const Program& program(ToneCurve curve, bool autoExposure);

  ProgramCache& programs_;
  // By ToneCurve and automatic exposure, once compiled.
  std::array<std::array<const Program*, 2>, std::size(kToneCurves)> programsByCurve_{};
  UniformBuffer<PostBlock> block_{"post.block"};
};

}  // namespace pbr
