#version 450 core
// Second pass of light assignment, one invocation per light: the light's view-space sphere (cullSphere; kept for the
// cluster passes), then the screen tiles it can reach, found from its projected bounds so that the cost is the
// tiles a light touches, not all of them. A tile gets the light's bit in its mask (and the word's bit in its
// summary) when the sphere touches the box of the surfaces the tile's pixels see (cluster_occupancy.comp); the
// cluster passes then test only a tile's lights against its clusters' boxes. Masks are left all zero by
// cluster_clear.comp after each frame.
layout(local_size_x = 64) in;

#include "../common/frame.glsl"
#include "clusters.glsl"
#include "lights.glsl"

layout(std430, binding = CLUSTER_VIEW_LIGHTS_SSBO) writeonly buffer ViewLights { vec4 viewLights[]; };
#if SPOT_LIGHTS
layout(std430, binding = CLUSTER_VIEW_CONES_SSBO) writeonly buffer ViewCones { vec4 viewCones[]; };
#endif
layout(std430, binding = CLUSTER_OCCUPANCY_SSBO) readonly buffer Occupancy { uint occupancy[]; };
layout(std430, binding = CLUSTER_TILE_MASKS_SSBO) buffer TileMasks { uint tileMasks[]; };
layout(std430, binding = CLUSTER_TILE_WORDS_SSBO) buffer TileWords { uint tileWords[]; };

// The tiles the sphere's projection may cover: the screen rectangle of its view-space bounding box, widened by
// a pixel; every tile when the box reaches the eye plane. False when the rectangle misses the screen.
bool tileRectangle(vec4 sphere, out uvec2 first, out uvec2 last) {
  float nearDepth = -sphere.z - sphere.w, farDepth = -sphere.z + sphere.w;
  vec2 ndcLo = vec2(-1.0), ndcHi = vec2(1.0);
  if (nearDepth > 1e-6) {
    vec2 lo = sphere.xy - sphere.w, hi = sphere.xy + sphere.w;
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
vec4 gSphere;
#if SPOT_LIGHTS
vec4 gApexRange, gAxisCos;  // the view-space cone (clusters.glsl)
#endif
uvec2 gFirst;
uint gColumns, gTiles;

void visitTile(uint t) {
  if (t >= gTiles) return;
  uint tile = (gFirst.y + t / gColumns) * clusterGrid.dims.x + gFirst.x + t % gColumns;
  uint base = tileBoxBase(tile);
  vec3 lo, hi;
  if (!occupiedBox(uvec3(occupancy[base], occupancy[base + 1u], occupancy[base + 2u]),
                   uvec3(occupancy[base + 3u], occupancy[base + 4u], occupancy[base + 5u]), lo, hi) ||
      !sphereIntersectsAabb(gSphere.xyz, gSphere.w, lo, hi)) {
    return;
  }
#if SPOT_LIGHTS
  if (!coneIntersectsAabb(gApexRange, gAxisCos, lo, hi)) return;
#endif
  uint word = gLight / 32u;
  uint previous = atomicOr(tileMasks[tile * clusterMaskWords() + word], 1u << (gLight % 32u));
  if (previous == 0u) atomicOr(tileWords[tile * clusterSummaryWords() + word / 32u], 1u << (word % 32u));
}

void main() {
  gLight = gl_GlobalInvocationID.x;
  if (gLight >= clusterGrid.counts.x) return;
  vec3 axis;
  float cosOuter;
  vec4 bounds = cullSphere(gLight, axis, cosOuter);
  gSphere = vec4((frame.view * vec4(bounds.xyz, 1.0)).xyz, bounds.w);
  viewLights[gLight] = gSphere;
#if SPOT_LIGHTS
  vec4 pr = lights[gLight].positionRadius;
  gApexRange = vec4((frame.view * vec4(pr.xyz, 1.0)).xyz, pr.w * (1.0 + 1e-5));
  gAxisCos = vec4(mat3(frame.view) * axis, cosOuter);
  viewCones[2u * gLight] = gApexRange;
  viewCones[2u * gLight + 1u] = gAxisCos;
#endif
  uvec2 last;
  // A light of radius 0 reaches nothing (distanceAttenuation).
  if (!(gSphere.w > 0.0) || !tileRectangle(gSphere, gFirst, last)) return;
  gColumns = last.x - gFirst.x + 1u;
  gTiles = gColumns * (last.y - gFirst.y + 1u);
  // Four tiles per iteration for llvmpipe's limit of 65535 loop iterations per invocation (see deferred.comp).
  for (uint t = 0u; t < gTiles; t += 4u) {
    visitTile(t);
    visitTile(t + 1u);
    visitTile(t + 2u);
    visitTile(t + 3u);
  }
}
