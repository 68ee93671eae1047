#version 450 core
// One G-buffer channel as a picture over the final frame, decoded by readSurface exactly as the lighting pass
// sees it. GBUFFER_CHANNEL: 0 base colour (sRGB-encoded for display), 1 normals (world, 0.5 n + 0.5),
// 2 roughness, 3 metalness, 4 view depth (log scale between near and far, near white).
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
#if GBUFFER_CHANNEL == 0
    color = srgbEncode(s.baseColor);
#elif GBUFFER_CHANNEL == 1
    color = s.normal * 0.5 + 0.5;
#elif GBUFFER_CHANNEL == 2
    color = vec3(s.roughness);
#elif GBUFFER_CHANNEL == 3
    color = vec3(s.metalness);
#else
    // Log scale: equal steps for equal ratios of distance, as the exponential cluster slices are spread.
    float t = log(s.viewDepth / frame.clip.x) / log(frame.clip.y / frame.clip.x);
    color = vec3(1.0 - clamp(t, 0.0, 1.0));
#endif
  }
  imageStore(ldr, p, vec4(color, 1.0));
}
