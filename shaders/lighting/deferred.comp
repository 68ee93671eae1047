#version 450 core
// Deferred lighting, one invocation per pixel: the lights at the G-buffer's surface (shade_lights.glsl).
// LIGHTING_STATS counts light-pixel pairs per workgroup, LIGHTING_PAIR_IMAGE per pixel (for the efficiency debug
// view). The radiance image holds the emitted radiance the G-buffer pass wrote; reflected light is added to it.
// LIGHT_CHUNKS splits the light loop over several dispatches: for more list entries than one invocation may loop
// over, and, shading every light, for more lights than one uniform-buffer window holds. A workgroup shades one 8x8
// tile that holds a surface (surface_tiles.glsl); the BACKGROUND_TILES build writes the background of the others.
layout(local_size_x = 8, local_size_y = 8) in;

#include "../common/dealt_tiles.glsl"
#include "gbuffer_surface.glsl"
#include "shade_lights.glsl"
#include "surface_tiles.glsl"

// The radiance target's format (LightingPass::program): the qualifier must match the texture's, and HDR_MAX is
// its largest finite value, so that a clamp keeps the store from rounding to Inf.
#ifndef HDR_IMAGE_FORMAT
#define HDR_IMAGE_FORMAT rgba16f
#define HDR_MAX FP16_MAX
#endif
layout(HDR_IMAGE_FORMAT, binding = RADIANCE_IMAGE) uniform image2D radiance;

#if LIGHT_CHUNKS
// The running sum stays in float in partialRadiance between dispatches, so the result is that of one loop over all.
layout(rgba32f, binding = PARTIAL_RADIANCE_IMAGE) uniform image2D partialRadiance;
#endif

#if IBL
// The environment's unfiltered radiance along the pixel's view ray, the same ray readSurface would reconstruct.
vec3 background(ivec2 p) {
  vec2 ndc = (vec2(p) + 0.5) * frame.viewport.zw * 2.0 - 1.0;
  return iblSpecular(normalize(mat3(frame.inverseView) * viewRayAt(ndc)), 0.0);
}
#endif

// This workgroup's place in its list's dispatch (surface_tiles.glsl), and the list's length.
#if BACKGROUND_TILES
#define LISTED_TILES backgroundDispatch.w
#else
#define LISTED_TILES surfaceDispatch.w
#endif
uint listedGroup() { return gl_WorkGroupID.y * TILE_DISPATCH_ROW + gl_WorkGroupID.x; }

// This invocation's pixel: of the listed tile its workgroup is dealt, or, for a workgroup of the last row past the
// list, the frame's corner past its last pixel, which main() leaves as it leaves a tile's pixels past the frame's
// edge (a select, not a branch of its own: llvmpipe runs the whole shader under one more lane mask for a return).
ivec2 listedPixel() {
  uint listed = LISTED_TILES, group = listedGroup();
  uint i = dealtIndex(min(group, listed - 1u), listed);
#if BACKGROUND_TILES
  uint tile = tiles[tileGrid.y + i];
#else
  uint tile = tiles[i];
#endif
  ivec2 p = ivec2(uvec2(tile % tileGrid.x, tile / tileGrid.x) * gl_WorkGroupSize.xy + gl_LocalInvocationID.xy);
  return group < listed ? p : ivec2(frame.viewport.xy);
}

// A pixel without a surface: the environment behind it, nothing in the counts.
void writeBackground(ivec2 p) {
#if LIGHTING_PAIR_IMAGE
  imageStore(pairCounts, p, uvec4(0u));
#endif
#if SHADOW_LIGHT_IMAGE
  imageStore(shadowLight, p, vec4(0.0));
#endif
#if LIGHT_CHUNKS
  if (lightChunk.w == 0u) return;
#endif
#if IBL
  imageStore(radiance, p, vec4(finishShading(background(p)), 1.0));
#else
  imageStore(radiance, p, vec4(0.0, 0.0, 0.0, 1.0));
#endif
}

void main() {
  ivec2 p = listedPixel();
  if (any(greaterThanEqual(p, ivec2(frame.viewport.xy)))) return;
#if BACKGROUND_TILES
  writeBackground(p);
#else
  Surface s;
  if (!readSurface(p, s)) {
    writeBackground(p);
    return;
  }
  beginShading(s);
#if SHADOW_LIGHT_IMAGE
  gShadowLight = vec2(0.0);
#endif
#if UNLIT_MATERIALS
  bool lit = !s.unlit;
#else
  const bool lit = true;
#endif
  vec3 environment = lit ? shadeEnvironment(s) : vec3(0.0);
  // The G-buffer pass left the surface's emission in the radiance target; a clear coat darkens it (fresnel_coat).
#if MATERIAL_CLEARCOAT
  float emission = lit ? coatTransmission(s) : 1.0;
#else
  const float emission = 1.0;
#endif
#if LIGHT_CHUNKS
  gColor = lightChunk.z != 0u ? imageLoad(radiance, p).rgb * emission + environment
                              : imageLoad(partialRadiance, p).rgb;
#else
  gColor = imageLoad(radiance, p).rgb * emission + environment;
#endif
  gContributing = 0u;
  uint count = lit ? lightsToVisit(s, uvec2(p)) : 0u;
#if LIGHT_CHUNKS
  uint begin = min(lightChunk.x, count), end = min(lightChunk.y, count);
#else
  uint begin = 0u, end = count;
#endif
  visitLights(s, begin, end);
#if LIGHTING_STATS
  uint group = listedGroup();
  atomicAdd(groupPairs[group].x, end - begin);
  atomicAdd(groupPairs[group].y, gContributing);
#endif
#if LIGHTING_PAIR_IMAGE
  uvec2 pairs = uvec2(end - begin, gContributing);
#if LIGHT_CHUNKS
  if (lightChunk.z == 0u) pairs += imageLoad(pairCounts, p).xy;
#endif
  imageStore(pairCounts, p, uvec4(pairs, 0u, 0u));
#endif
#if SHADOW_LIGHT_IMAGE
#if LIGHT_CHUNKS
  if (lightChunk.z == 0u) gShadowLight += imageLoad(shadowLight, p).xy;
#endif
  imageStore(shadowLight, p, vec4(gShadowLight, 0.0, 0.0));
#endif
#if LIGHT_CHUNKS
  if (lightChunk.w == 0u) {
    imageStore(partialRadiance, p, vec4(gColor, 1.0));
    return;
  }
#endif
  // NaN compares false everywhere: keep only values known to be finite and non-negative.
  vec3 color = mix(vec3(0.0), gColor, greaterThanEqual(gColor, vec3(0.0)));
  imageStore(radiance, p, vec4(min(finishShading(color), vec3(HDR_MAX)), 1.0));
#endif
}
