#version 450 core
// HDR radiance -> display: exposure and a tone curve for PBR frames, a plain clamp for LDR (Blinn-Phong) frames,
// then exact sRGB encoding into RGBA8.
layout(local_size_x = 8, local_size_y = 8) in;

#include "aces.glsl"
#include "srgb.glsl"
#include "tone_curves.glsl"
#if AUTO_EXPOSURE
#include "exposure_state.glsl"
#endif

// Mirrors pbr::PostBlock (post/post_block.hpp).
layout(std140, binding = POST_UBO) uniform PostBlock {
  float exposure;  // with AUTO_EXPOSURE, the meter's exposure replaces it
  uint toneMap;  // 1: exposure + the tone curve (a TONE_CURVE_* define), 0: clamp
  uvec2 size;
} post;

layout(binding = 0) uniform sampler2D hdrIn;
layout(rgba8, binding = 0) uniform writeonly image2D ldrOut;

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(uvec2(p), post.size))) return;
  vec3 c = texelFetch(hdrIn, p, 0).rgb;
  if (post.toneMap == 0u) {
    c = clamp(c, 0.0, 1.0);
  } else {
#if AUTO_EXPOSURE
    c *= meter.exposure;
#else
    c *= post.exposure;
#endif
#if TONE_CURVE_ACES_HILL
    c = acesFitted(c);
#elif TONE_CURVE_ACES_NARKOWICZ
    c = acesNarkowicz(c);
#elif TONE_CURVE_KHRONOS_NEUTRAL
    c = khronosNeutral(c);
#elif TONE_CURVE_AGX
    c = agx(c);
#elif TONE_CURVE_REINHARD
    c = reinhard(c);
#elif TONE_CURVE_EXPONENTIAL
    c = exponentialCurve(c);
#elif TONE_CURVE_LINEAR
    c = clamp(c, 0.0, 1.0);
#else
#error "post.comp: no TONE_CURVE_* define chose a curve"
#endif
  }
  imageStore(ldrOut, p, vec4(srgbEncode(c), 1.0));
}
