// Mirrors pbr::ClusterBlock (lighting/cluster_block.hpp).
layout(std140, binding = CLUSTER_UBO) uniform ClusterBlock {
  uvec4 dims;     // tiles x, tiles y, depth slices, tile size in pixels
  vec4 slicing;   // near, margin of a box past its slice (in slices), slice scale, slice bias:
                  // slice = floor(log(depth) * scale + bias)
  uvec4 counts;   // lights in the frame, clusters, index-list capacity, stats enabled
  uvec4 window;   // the lights whose bits the masks hold: first, end; mask words per slot, slot capacity
} clusterGrid;

// Per cluster (mirrored by lighting/cluster_block.hpp): where its light indices start in the index list, and how many there are.
struct ClusterHeader {
  uint offset;
  uint count;
};


// The header offset of a cluster that holds no surface (cluster_occupancy.comp): it gets no list, and would be
// shaded by brute force if a pixel ever landed in it.
const uint CLUSTER_INACTIVE = 0xFFFFFFFFu;

uint clusterCount() { return clusterGrid.counts.y; }
uint tileCount() { return clusterGrid.dims.x * clusterGrid.dims.y; }

// A cluster's slot (cluster_activate.comp), CLUSTER_INACTIVE where it holds no surface; clusters with slots
// below the slot capacity have a light mask over the lights of the current window (window.x to window.y): word
// w, bit b for light window.x + 32 w + b; and a summary, a bit per mask word that has any bit set, so that the
// fill pass finds its lights without reading empty words.
uint slotMaskWords() { return clusterGrid.window.z; }
uint slotSummaryWords() { return (slotMaskWords() + 31u) / 32u; }
uint slotCapacity() { return clusterGrid.window.w; }
// After the clusters' slots, per screen tile, a bit per depth slice whose cluster has a slot, so that a light
// visits only the slots among the slices it spans.
uint tileSliceWords() { return (clusterGrid.dims.z + 31u) / 32u; }
uint tileSliceBase(uint tile) { return clusterCount() + tile * tileSliceWords(); }

// The occupancy boxes (cluster_occupancy.comp): per cluster, then per tile, the view-space AABB of the surface
// points its pixels see, as six words: the minimum corner as orderedBits, the maximum corner as ~orderedBits,
// so that atomicMin keeps both; all ones where no pixel is.
uint clusterBoxBase(uint cluster) { return 6u * cluster; }
uint tileBoxBase(uint tile) { return 6u * (clusterCount() + tile); }
// The same boxes decoded and padded (occupiedBox) by cluster_activate.comp, two vec4 each, clusters then tiles;
// an empty one inverted so that no sphere touches it.
uint tileBoxIndex(uint tile) { return clusterCount() + tile; }

// A float as an unsigned integer of the same order (negative below positive), so that integer atomics can keep a
// float minimum; orderedFloat inverts it.
uint orderedBits(float x) {
  uint u = floatBitsToUint(x);
  return (u & 0x80000000u) != 0u ? ~u : u | 0x80000000u;
}
float orderedFloat(uint u) { return uintBitsToFloat((u & 0x80000000u) != 0u ? u & 0x7FFFFFFFu : ~u); }

// An occupancy box from its six words, widened by 1e-4 of its largest coordinate magnitude plus 1e-6: far above
// the rounding between the points found here and those the lighting pass reconstructs and compares in world
// space, so a light missing the box reaches none of its pixels. False for a box no pixel grew.
bool occupiedBox(uvec3 minBits, uvec3 notMaxBits, out vec3 lo, out vec3 hi) {
  if (minBits.x == 0xFFFFFFFFu) return false;
  lo = vec3(orderedFloat(minBits.x), orderedFloat(minBits.y), orderedFloat(minBits.z));
  hi = vec3(orderedFloat(~notMaxBits.x), orderedFloat(~notMaxBits.y), orderedFloat(~notMaxBits.z));
  vec3 extent = max(abs(lo), abs(hi));
  float pad = 1e-4 * max(extent.x, max(extent.y, extent.z)) + 1e-6;
  lo -= pad;
  hi += pad;
  return true;
}

// Whether a cluster's list was written; one that did not fit the index list is shaded by brute force.
// Written so that offset + count cannot wrap.
bool listFits(ClusterHeader h) {
  uint capacity = clusterGrid.counts.z;
  return h.count <= capacity && h.offset <= capacity - h.count;
}

// Demand can exceed 32 bits (many clusters x many lights): sums saturate instead of wrapping.
uint addSaturated(uint a, uint b) { return a > 0xFFFFFFFFu - b ? 0xFFFFFFFFu : a + b; }

// The slice coordinate of a view depth: its integer part is the slice.
float sliceCoordinate(float viewDepth) { return log(viewDepth) * clusterGrid.slicing.z + clusterGrid.slicing.w; }

uint clampSlice(float s) { return uint(clamp(s, 0.0, float(clusterGrid.dims.z - 1u))); }

uint depthSlice(float viewDepth) { return clampSlice(floor(sliceCoordinate(viewDepth))); }

uint clusterIndex(uvec2 pixel, float viewDepth) {
  uvec2 tile = min(pixel / clusterGrid.dims.w, clusterGrid.dims.xy - 1u);
  return (depthSlice(viewDepth) * clusterGrid.dims.y + tile.y) * clusterGrid.dims.x + tile.x;
}

// Arvo 1990, "A Simple Method for Box-Sphere Intersection Testing": squared distance from the centre to the box.
bool sphereIntersectsAabb(vec3 center, float radius, vec3 lo, vec3 hi) {
  vec3 d = max(lo - center, 0.0) + max(center - hi, 0.0);
  return dot(d, d) <= radius * radius;
}

// A spot light's cone in view space (cluster_lights.comp writes it, for frames with spot lights): apex and range R,
// unit axis and the cosine of the outer angle; a point light's axis is zero and its cosine -1, which never culls.
// Whether the cone can reach the box: tested against the box's bounding sphere (Wronski 2017, "Cull that cone!"),
// the sphere's distance from the cone's side in the plane of the axis, never more than the true distance, so that
// the test culls only what the cone misses.
bool coneIntersectsAabb(vec4 apexRange, vec4 axisCos, vec3 lo, vec3 hi) {
  vec3 center = 0.5 * (lo + hi);
  float radius = 0.5 * length(hi - lo);
  vec3 v = center - apexRange.xyz;
  float along = dot(v, axisCos.xyz);
  float across = sqrt(max(dot(v, v) - along * along, 0.0));
  float cosOuter = axisCos.w, sinOuter = sqrt(max(1.0 - cosOuter * cosOuter, 0.0));
  bool outsideAngle = cosOuter * across - sinOuter * along > radius;
  return !(outsideAngle || along > radius + apexRange.w || along < -radius);
}
