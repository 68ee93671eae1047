#version 450 core
// HDR radiance -> display: exposure and ACES for PBR frames, a plain clamp for LDR (Blinn-Phong) frames,
// then exact sRGB encoding into RGBA8.
layout(local_size_x = 8, local_size_y = 8) in;

#include "aces.glsl"
#include "srgb.glsl"

// Mirrors pbr::PostBlock (post/post_block.hpp).
layout(std140, binding = POST_UBO) uniform PostBlock {
  float exposure;
  uint toneMap;  // 1: exposure + ACES, 0: clamp
  uvec2 size;
} post;

layout(binding = 0) uniform sampler2D hdrIn;
layout(rgba8, binding = 0) uniform writeonly image2D ldrOut;

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(uvec2(p), post.size))) return;
  vec3 c = texelFetch(hdrIn, p, 0).rgb;
  c = post.toneMap != 0u ? acesFitted(c * post.exposure) : clamp(c, 0.0, 1.0);
  imageStore(ldrOut, p, vec4(srgbEncode(c), 1.0));
}
