// Where the surfaces are: each surface point grows the view-space box of its cluster, so that lights are tested
// against the surfaces a cluster holds rather than its whole froxel, and clusters without surface get no list. A
// tile's box is the union of its clusters' (cluster_activate.comp), the same box as its points' but grown once per
// cluster rather than once per pixel: on llvmpipe each of a pixel's box reads is a load per lane. A point within
// 1e-3 of a slice boundary joins both clusters: the lighting passes compute the slice in other programs, whose
// logarithm may round the other way.
#include "surface.glsl"
#include "clusters.glsl"

layout(std430, binding = CLUSTER_OCCUPANCY_SSBO) buffer Occupancy { uint occupancy[]; };

// Most points leave a box as it is: a plain read saves the atomic.
void keepLess(uint word, uint value) {
  if (value < occupancy[word]) atomicMin(occupancy[word], value);
}

void growBox(uint base, vec3 p) {
  keepLess(base, orderedBits(p.x));
  keepLess(base + 1u, orderedBits(p.y));
  keepLess(base + 2u, orderedBits(p.z));
  keepLess(base + 3u, ~orderedBits(p.x));
  keepLess(base + 4u, ~orderedBits(p.y));
  keepLess(base + 5u, ~orderedBits(p.z));
}

#if CASTER_PLANES
// Mirrors pbr::CasterPlanesBlock: the CASTER_PLANES planar casters' planes in view space (pbr::CasterPlane), each
// with its thickness in x of its tolerance.
layout(std140, binding = CASTER_PLANES_UBO) uniform CasterPlanes {
  vec4 casterPlanes[MAX_CASTER_PLANES];
  vec4 casterPlaneTolerances[MAX_CASTER_PLANES];
};
// Bit 2i: a point lies on plane i's normal's side, 2i + 1 on the other (pbr::receiversAbove, receiversBelow).
layout(std430, binding = PLANE_SIDES_SSBO) buffer PlaneSides { uint planeSides; };

// Which sides of the planes the point p lies on, beyond the plane's thickness and 1e-4 of its depth (its
// reconstruction error is far below). The count is a define, so that the loop unrolls: llvmpipe ran a loop over a
// count from the block at 18 ns a pixel. The word is only written where a point adds a side, as few do.
void markPlaneSides(vec3 p) {
  float reconstruction = 1e-4 * abs(p.z);
  uint sides = 0u;
  for (uint i = 0u; i < CASTER_PLANES; ++i) {
    float s = dot(casterPlanes[i].xyz, p) + casterPlanes[i].w, t = casterPlaneTolerances[i].x + reconstruction;
    sides |= (s > t ? 1u : 0u) << (2u * i);
    sides |= (s < -t ? 2u : 0u) << (2u * i);
  }
  if ((sides & ~planeSides) != 0u) atomicOr(planeSides, sides);
}
#endif

// The surface point seen at pixel p with reversed-Z depth `depth` occupies its clusters.
void occupy(uvec2 p, float depth) {
  vec3 viewPos = viewPositionAt(vec2(p), depth);
#if CASTER_PLANES
  markPlaneSides(viewPos);
#endif
  uvec2 tileXY = min(p / clusterGrid.dims.w, clusterGrid.dims.xy - 1u);
  uint tile = tileXY.y * clusterGrid.dims.x + tileXY.x;
  float s = sliceCoordinate(-viewPos.z);
  uint lo = clampSlice(floor(s - 1e-3)), hi = clampSlice(floor(s + 1e-3));
  growBox(clusterBoxBase(lo * tileCount() + tile), viewPos);
  if (hi != lo) growBox(clusterBoxBase(hi * tileCount() + tile), viewPos);
}
