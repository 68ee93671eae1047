#version 450 core
// Shadow visibility in place of the final frame (pbr::ShadowDebugPass): per pixel, the luminance casting lights
// bring with their shadows over what they would bring without (SHADOW_LIGHT_IMAGE of the lighting pass), grey from
// black (fully shadowed) to white (fully lit), the no-data pattern where no casting light reaches; and the shadow
// atlas inset at the top right, its depth on a log scale with every square outlined in its light's colour.
layout(local_size_x = 8, local_size_y = 8) in;

#include "../common/frame.glsl"
#include "legend.glsl"

layout(rg32f, binding = SHADOW_LIGHT_IMAGE_UNIT) uniform readonly image2D shadowLight;  // with, without shadows
layout(binding = SHADOW_DEPTH_UNIT) uniform sampler2D atlasDepth;      // reversed Z, 0 where nothing was drawn
layout(binding = SHADOW_OWNER_UNIT) uniform usampler2D atlasOwners;    // per 16x16 cell: view + 1, light + 1
layout(rgba8, binding = 0) uniform writeonly image2D ldr;

vec3 legendRamp(float t) {
  return vec3(t);
}

// A light's outline colour: hues a golden angle apart, so that neighbouring lights differ.
vec3 lightColor(uint light) {
  float h = fract(float(light) * 0.618034);
  return clamp(abs(fract(h + vec3(0.0, 2.0 / 3.0, 1.0 / 3.0)) * 6.0 - 3.0) - 1.0, 0.0, 1.0);
}

uvec2 ownerAt(ivec2 texel) {
  ivec2 cells = textureSize(atlasOwners, 0);
  return texelFetch(atlasOwners, clamp(texel * cells / textureSize(atlasDepth, 0), ivec2(0), cells - 1), 0).xy;
}

// The atlas inset's colour at inset pixel q of a `side`-pixel square.
vec3 atlasInset(ivec2 q, int side) {
  int atlas = textureSize(atlasDepth, 0).x;
  ivec2 texel = q * atlas / side, left = (q - ivec2(1, 0)) * atlas / side, below = (q - ivec2(0, 1)) * atlas / side;
  uvec2 owner = ownerAt(texel);
  if (owner.x == 0u) return vec3(0.05);  // no square here
  // An outline where the pixel to the left or below belongs to another square, or at the inset's edge.
  if (q.x == 0 || q.y == 0 || ownerAt(left).x != owner.x || ownerAt(below).x != owner.x) {
    return lightColor(owner.y - 1u);
  }
  float depth = texelFetch(atlasDepth, texel, 0).r;
  // Reversed Z: 1 at the near plane; a perspective view's depth n / w spans three decades over the light's radius.
  return depth > 0.0 ? vec3(clamp(1.0 + log(depth) / log(1000.0), 0.0, 1.0) * 0.8 + 0.1) : vec3(0.0, 0.0, 0.15);
}

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = ivec2(frame.viewport.xy);
  if (any(greaterThanEqual(p, size))) return;
  vec2 light = imageLoad(shadowLight, p).xy;
  vec3 color = light.y > 0.0 ? vec3(clamp(light.x / light.y, 0.0, 1.0)) : noDataPattern(p);
  int side = min(size.x, size.y) * 9 / 20;
  ivec2 q = p - (size - ivec2(side));
  if (all(greaterThanEqual(q, ivec2(0)))) color = atlasInset(q, side);
  imageStore(ldr, p, vec4(drawLegend(p, size, color), 1.0));
}
