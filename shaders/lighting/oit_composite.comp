#version 450 core
// Weighted blended order-independent transparency's resolve (McGuire & Bavoil 2013, "Weighted Blended
// Order-Independent Transparency", JCGT 2(2)): the layers' weighted average colour covers 1 - R of what lies behind,
// R the product of their 1 - alpha (the revealage); pixels no layer reached (R = 1) are left as they are.
layout(local_size_x = 8, local_size_y = 8) in;

#include "../common/math.glsl"

layout(binding = OIT_ACCUMULATION_UNIT) uniform sampler2D accumulation;  // sum of w a C, sum of w a
layout(binding = OIT_REVEALAGE_UNIT) uniform sampler2D revealage;        // product of 1 - a
layout(HDR_IMAGE_FORMAT, binding = RADIANCE_IMAGE) uniform image2D radiance;

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(radiance)))) return;
  float revealed = texelFetch(revealage, p, 0).r;
  if (revealed >= 1.0) return;
  vec4 sums = texelFetch(accumulation, p, 0);
  vec3 average = sums.rgb / max(sums.a, 1e-5);
  vec3 color = average * (1.0 - revealed) + imageLoad(radiance, p).rgb * revealed;
  // NaN compares false everywhere: keep only values known to be finite and non-negative.
  color = mix(vec3(0.0), color, greaterThanEqual(color, vec3(0.0)));
  imageStore(radiance, p, vec4(min(color, vec3(HDR_MAX)), 1.0));
}
