#version 450 core
// Deferred lighting: one invocation per pixel, every light of the frame (the brute-force reference path).
layout(local_size_x = 8, local_size_y = 8) in;

#include "surface.glsl"
#include "lights.glsl"
#if SHADING_MODEL_BLINN_PHONG
#include "model_blinn_phong.glsl"
#else
#include "model_pbr.glsl"
#endif

layout(rgba16f, binding = 0) uniform writeonly image2D hdrOut;

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, ivec2(frame.viewport.xy)))) return;
  Surface s;
  if (!readSurface(p, s)) {
    imageStore(hdrOut, p, vec4(0.0, 0.0, 0.0, 1.0));
    return;
  }
  vec3 color = shadeAmbient(s);
  uint count = lighting.counts.x;
  for (uint i = 0u; i < count; ++i) color += shadeLight(s, lights[i]);
  // NaN compares false everywhere: keep only values known to be finite and non-negative.
  color = mix(vec3(0.0), color, greaterThanEqual(color, vec3(0.0)));
  imageStore(hdrOut, p, vec4(finishShading(color), 1.0));
}
