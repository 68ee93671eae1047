#version 450 core
// One G-buffer channel as a picture over the final frame, decoded by readSurface exactly as the lighting pass
// sees it. One of GBUFFER_CHANNEL_BASE_COLOR (sRGB-encoded for display), _NORMAL (world, 0.5 n + 0.5),
// _ROUGHNESS, _METALNESS or _DEPTH (view depth, log scale between near and far, near white) is defined.
layout(local_size_x = 8, local_size_y = 8) in;

#include "surface.glsl"
#include "../post/srgb.glsl"

layout(rgba8, binding = 0) uniform writeonly image2D ldr;

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, ivec2(frame.viewport.xy)))) return;
  Surface s;
  vec3 color = vec3(0.0);
  if (readSurface(p, s)) {
#if defined(GBUFFER_CHANNEL_BASE_COLOR)
    color = srgbEncode(s.baseColor);
#elif defined(GBUFFER_CHANNEL_NORMAL)
    color = s.normal * 0.5 + 0.5;
#elif defined(GBUFFER_CHANNEL_ROUGHNESS)
    color = vec3(s.roughness);
#elif defined(GBUFFER_CHANNEL_METALNESS)
    color = vec3(s.metalness);
#elif defined(GBUFFER_CHANNEL_DEPTH)
    // Log scale: equal steps for equal ratios of distance, as the exponential cluster slices are spread.
    float t = log(s.viewDepth / frame.clip.x) / log(frame.clip.y / frame.clip.x);
    color = vec3(1.0 - clamp(t, 0.0, 1.0));
#else
#error one GBUFFER_CHANNEL_* must be defined
#endif
  }
  imageStore(ldr, p, vec4(color, 1.0));
}
