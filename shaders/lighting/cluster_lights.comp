#version 450 core
// Third pass of light assignment, LIGHTS_PER_INVOCATION lights per invocation: each light's view-space sphere,
// the screen tiles its projected bounds can cover and, in each tile whose surface box it touches, the clusters of
// the depth slices its sphere spans (widened by how far a box may pass its slice, sliceMargin), each tested
// against the box of the surfaces it holds (cluster_activate.comp). Cost: lights x the clusters they can reach.
// A hit counts the light in the cluster's header (LIGHT_COUNT) and/or sets its bit in the cluster's mask
// (LIGHT_MARK), from which cluster_fill.comp writes the list in light order. In each tile, only the slices whose
// cluster has a slot are visited (tileSliceBase). A light whose tiles x slices could loop past INLINE_CANDIDATES
// iterations, or past what its invocation's earlier lights left of INVOCATION_CANDIDATES, is queued instead and
// visited by the BIG_LIGHTS build, a workgroup per light sharing its tiles, so that no invocation loops past
// llvmpipe's limit of 65535 iterations (see deferred.comp). With EVERY_LIGHT that build takes every light of
// lightRange, one per workgroup, without the inline pass: the parallelism a GPU needs when lights are few and
// large (LightClusters::lightPassShape). The PER_CLUSTER build turns the loops around, as most GPU clustered
// renderers do: an invocation per cluster slot, its workgroup preparing 64 lights at a time into shared memory
// and each invocation testing its cluster against them, with the same tests in the same order of reasoning (the
// light's tile rectangle and slices, its tile's box, its cluster's box), so that it sets the same bits, gathered
// into whole mask words before they are written. Cost: lights x clusters holding a surface; the shape for few
// lights and clusters on a GPU.
#if BIG_LIGHTS
layout(local_size_x = 256) in;
#else
layout(local_size_x = 64) in;
#endif

#include "../common/frame.glsl"
#include "clusters.glsl"
#include "lights.glsl"

// x: the first light, y: the end of the lights this dispatch visits.
layout(location = 0) uniform uvec4 lightRange;

const uint INLINE_CANDIDATES = 16384u;  // per light
const uint INVOCATION_CANDIDATES = 49152u;  // per invocation, its lights together

layout(std430, binding = CLUSTER_BOXES_SSBO) readonly buffer Boxes { vec4 boxes[]; };
layout(std430, binding = CLUSTER_SLOTS_SSBO) readonly buffer Slots { uint clusterSlots[]; };
layout(std430, binding = BIG_LIGHTS_SSBO) buffer BigLights {
  uvec4 bigDispatch;  // glDispatchComputeIndirect's workgroup counts (x: lights queued), set to (0, 1, 1) before
  uint bigLights[];
};
#if LIGHT_COUNT
layout(std430, binding = CLUSTER_SSBO) buffer Headers { ClusterHeader headers[]; };
#if ASSIGN_STATS
layout(std430, binding = LIGHT_VISIBLE_SSBO) writeonly buffer Visible { uint lightVisible[]; };
#endif
#endif
#if LIGHT_MARK
#define SLOT_MASKS_QUALIFIER
#include "slot_masks.glsl"

// Sets a bit of the slot's mask word or summary word `i` (slot_masks.glsl); returns the word as it was.
uint orSlotWord(bool high, uint i, uint bits) { return high ? atomicOr(masksHigh[i], bits) : atomicOr(masksLow[i], bits); }
#endif

// The sphere outside which a light lights nothing: its own, or for a spot light the smallest around the sector
// of it within the outer cone (Wronski 2017, "Cull that cone!"): about the cap for cones wider than 45 degrees,
// else through the apex and the cap's rim. `cosOuter` is the cone's, widened by 1e-4, and R the range, widened by
// 1e-5 of itself: more than float rounding moves the shader's falloff test, so that culling stays conservative.
// A point light's cosOuter is -1.
vec4 cullSphere(uint light, out vec3 axis, out float cosOuter) {
  vec4 pr = lights[light].positionRadius;
  axis = vec3(0.0);
  cosOuter = -1.0;
#if SPOT_LIGHTS
  vec4 cone = spotCones[light];
  float s = length(cone.xyz);
  if (s == 0.0) return pr;
  axis = cone.xyz / s;
  cosOuter = max(-cone.w / s - 1e-4, -1.0);
  pr.w *= 1.0 + 1e-5;
  if (cosOuter <= 0.0) return pr;
  if (cosOuter <= 0.70710678) {
    return vec4(pr.xyz + axis * (pr.w * cosOuter), pr.w * sqrt(1.0 - cosOuter * cosOuter));
  }
  float r = pr.w / (2.0 * cosOuter);
  return vec4(pr.xyz + axis * r, r);
#else
  return pr;
#endif
}

uint gLight;
vec4 gSphere;  // view space
#if SPOT_LIGHTS
vec4 gApexRange, gAxisCos;  // the view-space cone (clusters.glsl)
#endif
uvec2 gFirst, gLast;
uint gColumns, gTiles, gSliceFirst, gSliceLast;
bool gHit;

// The tiles the sphere's projection may cover: the screen rectangle of its view-space bounding box, widened by
// a pixel; in perspective every tile when the box reaches the eye plane. False when the rectangle misses the
// screen.
bool tileRectangle(vec4 sphere, out uvec2 first, out uvec2 last) {
  float nearDepth = -sphere.z - sphere.w, farDepth = -sphere.z + sphere.w;
  vec2 ndcLo = vec2(-1.0), ndcHi = vec2(1.0);
  vec2 lo = sphere.xy - sphere.w, hi = sphere.xy + sphere.w;
  if (frame.clip.w != 0.0) {  // orthographic: x and y do not shrink with depth
    ndcLo = lo * frame.projParams.xy;
    ndcHi = hi * frame.projParams.xy;
  } else if (nearDepth > 1e-6) {
    ndcLo = min(lo / nearDepth, lo / farDepth) * frame.projParams.xy;
    ndcHi = max(hi / nearDepth, hi / farDepth) * frame.projParams.xy;
  }
  vec2 pixelLo = (ndcLo * 0.5 + 0.5) * frame.viewport.xy - 1.0;
  vec2 pixelHi = (ndcHi * 0.5 + 0.5) * frame.viewport.xy + 1.0;
  if (farDepth <= 0.0 || any(lessThan(pixelHi, vec2(0.0))) || any(greaterThanEqual(pixelLo, frame.viewport.xy))) {
    return false;
  }
  vec2 lastTile = vec2(clusterGrid.dims.xy - 1u);
  first = uvec2(clamp(floor(pixelLo / float(clusterGrid.dims.w)), vec2(0.0), lastTile));
  last = uvec2(clamp(floor(pixelHi / float(clusterGrid.dims.w)), vec2(0.0), lastTile));
  return true;
}

// How far, in slices, a cluster's box may reach past its slice (LightClusters::rebuildGrid).
float sliceMargin() { return clusterGrid.slicing.y; }

// The light's view-space bounds, the tiles and the slices it may reach. False when it reaches nothing: radius 0
// (distanceAttenuation), or outside the screen.
bool prepareLight(uint light) {
  gLight = light;
  vec3 axis;
  float cosOuter;
  vec4 bounds = cullSphere(light, axis, cosOuter);
  gSphere = vec4((frame.view * vec4(bounds.xyz, 1.0)).xyz, bounds.w);
#if SPOT_LIGHTS
  vec4 pr = lights[light].positionRadius;
  gApexRange = vec4((frame.view * vec4(pr.xyz, 1.0)).xyz, pr.w * (1.0 + 1e-5));
  gAxisCos = vec4(mat3(frame.view) * axis, cosOuter);
#endif
  if (!(gSphere.w > 0.0) || !tileRectangle(gSphere, gFirst, gLast)) return false;
  gColumns = gLast.x - gFirst.x + 1u;
  gTiles = gColumns * (gLast.y - gFirst.y + 1u);
  float nearDepth = -gSphere.z - gSphere.w, farDepth = -gSphere.z + gSphere.w;
  gSliceFirst = nearDepth > 0.0 ? clampSlice(floor(sliceCoordinate(nearDepth) - sliceMargin())) : 0u;
  gSliceLast = clampSlice(floor(sliceCoordinate(farDepth) + sliceMargin()));
  return true;
}

// A cluster with a slot (visitTile finds them through the tile's slice bits).
void visitCluster(uint cluster) {
  vec3 lo = boxes[2u * cluster].xyz, hi = boxes[2u * cluster + 1u].xyz;
  if (!sphereIntersectsAabb(gSphere.xyz, gSphere.w, lo, hi)) return;
#if SPOT_LIGHTS
  if (!coneIntersectsAabb(gApexRange, gAxisCos, lo, hi)) return;
#endif
  gHit = true;
#if LIGHT_COUNT
  atomicAdd(headers[cluster].count, 1u);
#endif
#if LIGHT_MARK
  uint slot = clusterSlots[cluster];
  uint bit = gLight - clusterGrid.window.x, word = bit / 32u;
  bool high = slotIsHigh(slot);
  uint previous = orSlotWord(high, slotMaskBase(slot) + word, 1u << (bit % 32u));
  if (previous == 0u) orSlotWord(high, slotSummaryBase(slot) + word / 32u, 1u << (word % 32u));
#endif
}

// The t-th tile of the light's rectangle (t < gTiles).
void visitTile(uint t) {
  uint tile = (gFirst.y + t / gColumns) * clusterGrid.dims.x + gFirst.x + t % gColumns;
  uint box = 2u * tileBoxIndex(tile);
  if (!sphereIntersectsAabb(gSphere.xyz, gSphere.w, boxes[box].xyz, boxes[box + 1u].xyz)) return;
#if SPOT_LIGHTS
  if (!coneIntersectsAabb(gApexRange, gAxisCos, boxes[box].xyz, boxes[box + 1u].xyz)) return;
#endif
  uint base = tileSliceBase(tile);
  for (uint w = gSliceFirst / 32u; w <= gSliceLast / 32u; ++w) {
    uint first = max(gSliceFirst, 32u * w) - 32u * w, last = min(gSliceLast, 32u * w + 31u) - 32u * w;
    uint bits = clusterSlots[base + w] & (0xFFFFFFFFu << first) & (0xFFFFFFFFu >> (31u - last));
    while (bits != 0u) {
      visitCluster((32u * w + uint(findLSB(bits))) * tileCount() + tile);
      bits &= bits - 1u;
    }
  }
}

void finishLight() {
#if LIGHT_COUNT && ASSIGN_STATS
  if (gHit) lightVisible[gLight] = 1u;
#endif
}

#if PER_CLUSTER
layout(std430, binding = SLOT_CLUSTERS_SSBO) readonly buffer SlotClusters {
  uint activeCount;
  uint slotClusters[];
};

// A batch of prepared lights (prepareLight's results), one per invocation of the workgroup; a light that reaches
// nothing has an empty slice range.
shared vec4 sSphere[64];
shared uvec4 sTiles[64];   // first x, first y, last x, last y
shared uvec2 sSlices[64];  // first, last
#if SPOT_LIGHTS
shared vec4 sApexRange[64], sAxisCos[64];
#endif

// The mask word a cluster's invocation is gathering bits for (~0u: none yet), flushed as visitCluster writes it.
uint gWord = ~0u, gBits = 0u;
void flushWord(uint slot) {
#if LIGHT_MARK
  if (gBits == 0u) return;
  bool high = slotIsHigh(slot);
  uint previous = orSlotWord(high, slotMaskBase(slot) + gWord, gBits);
  if (previous == 0u) orSlotWord(high, slotSummaryBase(slot) + gWord / 32u, 1u << (gWord % 32u));
  gBits = 0u;
#endif
}

// Per cluster slot, lights lightRange.x to lightRange.y in batches of 64; slots from lightRange.z on.
void perCluster() {
  uint slotted = min(activeCount, slotCapacity());
  if (lightRange.z + gl_WorkGroupID.x * gl_WorkGroupSize.x >= slotted) return;  // the whole workgroup
  uint slot = lightRange.z + gl_GlobalInvocationID.x;
  bool mine = slot < slotted;
  uint cluster = mine ? slotClusters[slot] : 0u;
  uint tile = cluster % tileCount(), slice = cluster / tileCount();
  uvec2 tileXY = uvec2(tile % clusterGrid.dims.x, tile / clusterGrid.dims.x);
  uint box = 2u * tileBoxIndex(tile);
  vec3 tileLo = boxes[box].xyz, tileHi = boxes[box + 1u].xyz;
  vec3 lo = boxes[2u * cluster].xyz, hi = boxes[2u * cluster + 1u].xyz;
  uint hits = 0u;
  for (uint first = lightRange.x; first < lightRange.y; first += gl_WorkGroupSize.x) {
    barrier();  // the previous batch is read
    uint i = gl_LocalInvocationIndex;
    bool reaches = first + i < lightRange.y && prepareLight(first + i);
    sSphere[i] = gSphere;
    sTiles[i] = uvec4(gFirst, gLast);
    sSlices[i] = reaches ? uvec2(gSliceFirst, gSliceLast) : uvec2(1u, 0u);
#if SPOT_LIGHTS
    sApexRange[i] = gApexRange;
    sAxisCos[i] = gAxisCos;
#endif
    barrier();
    if (!mine) continue;
    uint batch = min(gl_WorkGroupSize.x, lightRange.y - first);
    for (uint j = 0u; j < batch; ++j) {
      uvec4 rect = sTiles[j];
      uvec2 slices = sSlices[j];
      if (slice < slices.x || slice > slices.y || any(lessThan(tileXY, rect.xy)) || any(greaterThan(tileXY, rect.zw))) {
        continue;
      }
      vec4 sphere = sSphere[j];
      if (!sphereIntersectsAabb(sphere.xyz, sphere.w, tileLo, tileHi)) continue;
#if SPOT_LIGHTS
      if (!coneIntersectsAabb(sApexRange[j], sAxisCos[j], tileLo, tileHi)) continue;
#endif
      if (!sphereIntersectsAabb(sphere.xyz, sphere.w, lo, hi)) continue;
#if SPOT_LIGHTS
      if (!coneIntersectsAabb(sApexRange[j], sAxisCos[j], lo, hi)) continue;
#endif
      ++hits;
#if LIGHT_COUNT && ASSIGN_STATS
      lightVisible[first + j] = 1u;
#endif
#if LIGHT_MARK
      uint bit = first + j - clusterGrid.window.x;
      if (bit / 32u != gWord) {
        flushWord(slot);
        gWord = bit / 32u;
      }
      gBits |= 1u << (bit % 32u);
#endif
    }
  }
  if (!mine) return;
  flushWord(slot);
#if LIGHT_COUNT
  if (hits != 0u) atomicAdd(headers[cluster].count, hits);
#endif
}
#endif

void main() {
#if PER_CLUSTER
  perCluster();
#elif BIG_LIGHTS
  gHit = false;
#if EVERY_LIGHT
  if (!prepareLight(lightRange.x + gl_WorkGroupID.x)) return;
#else
  if (!prepareLight(bigLights[gl_WorkGroupID.x])) return;
#endif
  for (uint t = gl_LocalInvocationIndex; t < gTiles; t += gl_WorkGroupSize.x) visitTile(t);
  finishLight();
#else
  // Several lights per invocation: llvmpipe spends about as much starting an invocation as preparing a light.
  // Invocation i takes lights i, i + n, i + 2n, ... (n invocations): at each step the lanes of a SIMD group hold
  // neighbouring lights (the buffer's Z order, light_order.hpp), alike in the tiles and slices they loop over,
  // while an invocation's own lights lie far apart, so that no invocation runs a chain of large lights alone.
  uint invocations = (lightRange.y - lightRange.x + LIGHTS_PER_INVOCATION - 1u) / LIGHTS_PER_INVOCATION;
  if (gl_GlobalInvocationID.x >= invocations) return;
  uint iterations = 0u;
  for (uint light = lightRange.x + gl_GlobalInvocationID.x; light < lightRange.y; light += invocations) {
    gHit = false;
    if (!prepareLight(light)) continue;
    // A tile takes its own iteration, at most (slices / 32 + 2) words and `slices` bits: within the
    // 2 (slices + 1) counted for it.
    uint candidates = gTiles * 2u * (gSliceLast - gSliceFirst + 2u);
    if (candidates > INLINE_CANDIDATES || candidates > INVOCATION_CANDIDATES - iterations) {
      bigLights[atomicAdd(bigDispatch.x, 1u)] = light;
      continue;
    }
    iterations += candidates;
    // A tile per iteration: llvmpipe runs each call of an unrolled loop for all eight lanes of its SIMD group,
    // even where none has the tile, and most lights of a million cover one tile.
    for (uint t = 0u; t < gTiles; ++t) visitTile(t);
    finishLight();
  }
#endif
}
