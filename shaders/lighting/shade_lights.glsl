// The lights at a surface point, shared by the deferred pass (deferred.comp) and the forward pass of BLEND surfaces
// (forward.frag): the same light lists, the same models and the same shadow lookups. CLUSTERED 0 shades every
// light of the frame (the brute-force reference path); CLUSTERED 1 shades only the lights listed for the point's
// cluster, in the same ascending order, so both paths produce the same sums. IBL (PBR only) lights with the
// environment maps of pbr::IblMaps instead of the uniform ambient radiance.
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

#if LIGHT_CHUNKS
// This dispatch or draw visits the lights [x, y) of what lightsToVisit counts, in order; z: 1 for the frame's first,
// w: 1 for its last (LightingPass).
layout(location = 0) uniform uvec4 lightChunk;
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
// directional lights (shadowed where they cast), added in their order. DIRECTIONAL_LIGHTS is their count (0 leaves
// the loop out, which llvmpipe would run once under an empty lane mask even over no light; a constant count unrolls
// it, each light's entries read at a constant index, pbr::LightKinds).
vec3 shadeEnvironment(Surface s) {
#if IBL && (MATERIAL_CLEARCOAT || MATERIAL_SHEEN)
  vec3 color = shadeIbl(s.normal, s.V, s.baseColor, s.roughness, s.metalness, 1.0);
#if MATERIAL_SHEEN
  // The sheen lobe reflects E of the environment prefiltered by its Charlie lobe about the normal (N = V).
  if (s.sheenColor != vec3(0.0)) {
    color = gSheenScale * color + s.sheenColor * gSheenE * iblSheen(s.normal, s.sheenRoughness);
  }
#endif
#if MATERIAL_CLEARCOAT
  // The coat reflects the environment along its own normal, with its lobe's albedo at F 1.
  if (s.clearcoat > 0.0) {
    vec2 coatDfg = iblDfg(gCoatNoV, s.clearcoatRoughness);
    vec3 coat = iblSpecular(reflect(-s.V, s.clearcoatNormal), s.clearcoatRoughness) * (coatDfg.x + coatDfg.y);
    color = (1.0 - gCoatWeight) * color + gCoatWeight * coat;
  }
#endif
  color *= s.occlusion;
#elif IBL
  vec3 color = shadeIbl(s.normal, s.V, s.baseColor, s.roughness, s.metalness, s.occlusion);
#else
  vec3 color = shadeAmbient(s);
#endif
#if DIRECTIONAL_LIGHTS
  for (uint i = 0u; i < uint(DIRECTIONAL_LIGHTS); ++i) {
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
#endif
  return color;
}


// How many lights the surface at `pixel` visits: its cluster's list entries (all lights where the list did not fit
// the index list), or every light when shading every light.
uint lightsToVisit(Surface s, uvec2 pixel) {
#if CLUSTERED
  gHeader = headers[clusterIndex(pixel, s.viewDepth)];
  gListed = listFits(gHeader);
  return gListed ? gHeader.count : lighting.counts.x;
#else
  return lighting.counts.x;
#endif
}

// Adds the lights [begin, end) of those lightsToVisit counted to gColor.
void visitLights(Surface s, uint begin, uint end) {
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
}
