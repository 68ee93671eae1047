#version 450 core
// Deferred lighting, one invocation per pixel. CLUSTERED 0 shades every light of the frame (the brute-force
// reference path); CLUSTERED 1 shades only the lights listed for the pixel's cluster, in the same ascending
// order, so both paths produce the same sums. LIGHTING_STATS counts light-pixel pairs per workgroup,
// LIGHTING_PAIR_IMAGE per pixel (for the efficiency debug view). IBL (PBR
// only) lights with the environment maps of pbr::IblMaps instead of the uniform ambient radiance. The radiance
// image holds the emitted radiance the G-buffer pass wrote; reflected light is added to it. LIGHT_CHUNKS splits
// the light loop over several dispatches: for more list entries than one invocation may loop over, and, shading
// every light, for more lights than one uniform-buffer window holds.
layout(local_size_x = 8, local_size_y = 8) in;

#include "surface.glsl"
#include "lights.glsl"
#include "directional_lights.glsl"
#if SHADING_MODEL_BLINN_PHONG
#include "model_blinn_phong.glsl"
#else
#include "model_pbr.glsl"
#endif
#if IBL
// Image-based lighting (PBR only): the environment's split-sum lighting replaces the uniform ambient term, and
// pixels without geometry show the environment itself.
#if SHADING_MODEL_BLINN_PHONG
#error "IBL is a PBR permutation: Blinn-Phong keeps its LDR ambient term and black background"
#endif
#include "../ibl/ibl_sample.glsl"
#endif
#if SHADOWS
// Lights with shadow views are shaded with their visibility (shaders/shadows/shadow_sample.glsl); both culling
// paths look it up for the same light and point, so their frames stay identical.
#include "../shadows/shadow_sample.glsl"
#endif
#if CLUSTERED
#include "clusters.glsl"
layout(std430, binding = CLUSTER_SSBO) readonly buffer Headers { ClusterHeader headers[]; };
layout(std430, binding = LIGHT_INDEX_SSBO) readonly buffer Indices { uint lightIndices[]; };
#else
// Shading every light, all invocations read the same light at once: from a uniform block llvmpipe loads it once
// for the SIMD row, where a storage-buffer read is a bounds-checked load per lane (about 5 ns of a 7 ns pair).
// The window holds the dispatch's lights (LightBuffer::bindWindow).
layout(std140, binding = LIGHT_WINDOW_UBO) uniform LightWindow { PointLight windowLights[LIGHT_WINDOW]; };
#if SPOT_LIGHTS
layout(std140, binding = SPOT_WINDOW_UBO) uniform SpotWindow { vec4 windowCones[LIGHT_WINDOW]; };
#endif
#endif
#if LIGHTING_STATS
// Per workgroup: light-pixel pairs evaluated, and pairs that contribute (attenuation > 0 and n.l > 0).
layout(std430, binding = LIGHTING_STATS_SSBO) buffer PairStats { uvec2 groupPairs[]; };
#endif
#if LIGHTING_PAIR_IMAGE
// Per pixel: the same two counts, summed over the dispatches of LIGHT_CHUNKS.
layout(rg32ui, binding = PAIR_COUNT_IMAGE) uniform uimage2D pairCounts;
#endif
#define COUNT_PAIRS (LIGHTING_STATS || LIGHTING_PAIR_IMAGE)
#if SHADOW_LIGHT_IMAGE
// Per pixel: the luminance casting lights bring with their shadows and without, summed over the dispatches of
// LIGHT_CHUNKS, for the shadows debug view.
layout(rg32f, binding = SHADOW_LIGHT_IMAGE_UNIT) uniform image2D shadowLight;
vec2 gShadowLight;
// The light's luminance before and after its visibility v (Rec. 709 weights).
void addShadowLight(vec3 c, float v) {
  float y = dot(c, vec3(0.2126, 0.7152, 0.0722));
  gShadowLight += vec2(y * v, y);
}
#endif

// The radiance target's format (LightingPass::program): the qualifier must match the texture's, and HDR_MAX is
// its largest finite value, so that a clamp keeps the store from rounding to Inf.
#ifndef HDR_IMAGE_FORMAT
#define HDR_IMAGE_FORMAT rgba16f
#define HDR_MAX FP16_MAX
#endif
layout(HDR_IMAGE_FORMAT, binding = RADIANCE_IMAGE) uniform image2D radiance;

#if LIGHT_CHUNKS
// This dispatch visits the pixel's list positions (or, shading every light, the lights) [x, y), in order; the
// running sum stays in float in partialRadiance between dispatches, so the result is that of one loop over all.
// z: 1 for the first dispatch, w: 1 for the last (LightingPass::render).
layout(location = 0) uniform uvec4 lightChunk;
layout(rgba32f, binding = PARTIAL_RADIANCE_IMAGE) uniform image2D partialRadiance;
#endif

#if COUNT_PAIRS
bool contributes(Surface s, PointLight light, vec4 cone) {
  float d2;
  vec3 L = directionToLight(s.position, s.normal, light, d2);
  return dot(s.normal, L) > 0.0 && lightAttenuation(d2, L, light, cone) > 0.0;
}
#endif

#if CLUSTERED
ClusterHeader gHeader;
bool gListed;
#else
uint gWindowStart;  // the light in windowLights[0]
#endif
vec3 gColor;
uint gContributing;

// The k-th light this pixel visits: its cluster's k-th entry, or light k when shading every light.
void visitLight(Surface s, uint k) {
#if CLUSTERED
  uint index = gListed ? lightIndices[gHeader.offset + k] : k;
  PointLight light = lights[index];
#if SPOT_LIGHTS
  vec4 cone = spotCones[index];
#endif
#else
  uint index = k;
  PointLight light = windowLights[k - gWindowStart];
#if SPOT_LIGHTS
  vec4 cone = windowCones[k - gWindowStart];
#endif
#endif
#if !SPOT_LIGHTS
  const vec4 cone = vec4(0.0, 0.0, 0.0, 1.0);
#endif
#if SHADOWS
  vec3 c = shadeLight(s, light, cone);
  uint entry = lightShadow[index];
  if (entry != 0u && c.r + c.g + c.b > 0.0) {
    float d2;
    vec3 L = directionToLight(s.position, s.normal, light, d2);
    float v = lightShadowVisibility(entry, light.positionRadius, cone, s.position, s.normal, L);
#if SHADOW_LIGHT_IMAGE
    addShadowLight(c, v);
#endif
    c *= v;
  }
  gColor += c;
#else
  gColor += shadeLight(s, light, cone);
#endif
#if COUNT_PAIRS
  gContributing += contributes(s, light, cone) ? 1u : 0u;
#endif
}

// Light arriving from everything but the point lights: the environment (or uniform ambient light) and the
// directional lights (shadowed where they cast), added in their order.
vec3 shadeEnvironment(Surface s) {
#if IBL
  vec3 color = shadeIbl(s.normal, s.V, s.baseColor, s.roughness, s.metalness, s.occlusion);
#else
  vec3 color = shadeAmbient(s);
#endif
  for (uint i = 0u; i < directionalCount.x; ++i) {
#if SHADOWS
    vec3 c = shadeDirectional(s, directionalLights[i]);
    if (directionalShadow[i].x != 0u && c.r + c.g + c.b > 0.0) {
      float v = directionalShadowVisibility(i, s.viewDepth, s.position, s.normal, directionalLights[i].toLight.xyz);
#if SHADOW_LIGHT_IMAGE
      addShadowLight(c, v);
#endif
      c *= v;
    }
    color += c;
#else
    color += shadeDirectional(s, directionalLights[i]);
#endif
  }
  return color;
}

#if IBL
// The environment's unfiltered radiance along the pixel's view ray, the same ray readSurface would reconstruct.
vec3 background(ivec2 p) {
  vec2 ndc = (vec2(p) + 0.5) * frame.viewport.zw * 2.0 - 1.0;
  vec3 viewRay = vec3(ndc.x / frame.projParams.x, ndc.y / frame.projParams.y, -1.0);
  return iblSpecular(normalize(mat3(frame.inverseView) * viewRay), 0.0);
}
#endif

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, ivec2(frame.viewport.xy)))) return;
  Surface s;
  if (!readSurface(p, s)) {
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
    return;
  }
  beginShading(s);
#if SHADOW_LIGHT_IMAGE
  gShadowLight = vec2(0.0);
#endif
#if LIGHT_CHUNKS
  gColor = lightChunk.z != 0u ? imageLoad(radiance, p).rgb + shadeEnvironment(s) : imageLoad(partialRadiance, p).rgb;
#else
  gColor = imageLoad(radiance, p).rgb + shadeEnvironment(s);
#endif
  gContributing = 0u;
#if CLUSTERED
  gHeader = headers[clusterIndex(uvec2(p), s.viewDepth)];
  gListed = listFits(gHeader);
  uint count = gListed ? gHeader.count : lighting.counts.x;
#else
  uint count = lighting.counts.x;
#endif
#if LIGHT_CHUNKS
  uint begin = min(lightChunk.x, count), end = min(lightChunk.y, count);
#else
  uint begin = 0u, end = count;
#endif
#if !CLUSTERED
  gWindowStart = begin;
#endif
  // llvmpipe ends an invocation after 65535 loop iterations in all (its guard against endless loops): a clustered
  // dispatch visits at most kLightsPerDispatch (32,768) list entries, one per iteration, and is not unrolled: each
  // copy of visitLight is another copy of the shading and shadow code, and on llvmpipe the larger shader runs slower
  // (unrolled by 8, the README's Blender export, shadowed, lit in 231 instead of 101 ms). Shading every light, a
  // dispatch visits one uniform window (2,048 lights at most), the same lights at every pixel, which runs faster
  // unrolled by 8 (about 12 % at 1,024 lights). Either way the lights are added one after another, in order.
#if CLUSTERED
  for (uint k = begin; k < end; ++k) visitLight(s, k);
#else
  uint k = begin;
  for (; k + 8u <= end; k += 8u) {
    visitLight(s, k);
    visitLight(s, k + 1u);
    visitLight(s, k + 2u);
    visitLight(s, k + 3u);
    visitLight(s, k + 4u);
    visitLight(s, k + 5u);
    visitLight(s, k + 6u);
    visitLight(s, k + 7u);
  }
  for (; k < end; ++k) visitLight(s, k);
#endif
#if LIGHTING_STATS
  uint group = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
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
}
