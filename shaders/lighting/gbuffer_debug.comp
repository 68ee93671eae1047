#version 450 core
// One channel of the surface in place of the final frame, decoded by readSurface exactly as the lighting pass sees
// it, with its legend. One of GBUFFER_CHANNEL_BASE_COLOR (linear, sRGB-encoded for display), _NORMAL (world space,
// 0.5 n + 0.5), _ROUGHNESS (perceptual), _METALNESS, _OCCLUSION (ambient occlusion, 1 without a map), _DEPTH (view
// depth, log scale between the near and far planes, near white) or _EMISSION is defined. Pixels without a surface
// are black. EMISSION keeps the frame that post made of the radiance target while it held the emitted radiance
// alone (pbr::Renderer skips the lighting pass for it) and adds the legend.
layout(local_size_x = 8, local_size_y = 8) in;

#include "gbuffer_surface.glsl"
#include "legend.glsl"
#include "../post/srgb.glsl"

layout(rgba8, binding = 0) uniform image2D ldr;

vec3 legendRamp(float t) {
#if defined(GBUFFER_CHANNEL_DEPTH)
  return vec3(1.0 - t);
#else
  return vec3(t);
#endif
}

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = ivec2(frame.viewport.xy);
  if (any(greaterThanEqual(p, size))) return;
  Surface s;
  vec3 color = vec3(0.0);
#if defined(GBUFFER_CHANNEL_EMISSION)
  color = imageLoad(ldr, p).rgb;
#else
  if (readSurface(p, s)) {
#if defined(GBUFFER_CHANNEL_BASE_COLOR)
    color = srgbEncode(s.baseColor);
#elif defined(GBUFFER_CHANNEL_NORMAL)
    color = s.normal * 0.5 + 0.5;
#elif defined(GBUFFER_CHANNEL_ROUGHNESS)
    color = vec3(s.roughness);
#elif defined(GBUFFER_CHANNEL_METALNESS)
    color = vec3(s.metalness);
#elif defined(GBUFFER_CHANNEL_OCCLUSION)
    color = vec3(s.occlusion);
#elif defined(GBUFFER_CHANNEL_DEPTH)
    // Log scale: equal steps for equal ratios of distance, as the exponential cluster slices are spread.
    color = legendRamp(clamp(log(s.viewDepth / frame.clip.x) / log(frame.clip.y / frame.clip.x), 0.0, 1.0));
#else
#error one GBUFFER_CHANNEL_* must be defined
#endif
  }
#endif
  imageStore(ldr, p, vec4(drawLegend(p, size, color), 1.0));
}
