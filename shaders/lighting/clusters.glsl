// Mirrors pbr::ClusterBlock (lighting/cluster_block.hpp).
layout(std140, binding = CLUSTER_UBO) uniform ClusterBlock {
  uvec4 dims;     // tiles x, tiles y, depth slices, tile size in pixels
  vec4 slicing;   // near, far, slice scale, slice bias: slice = floor(log(depth) * scale + bias)
  uvec4 counts;   // lights in the frame, clusters, index-list capacity, stats enabled
} clusterGrid;

// Per cluster (mirrored by lighting/cluster_block.hpp): where its light indices start in the index list, and how many there are.
struct ClusterHeader {
  uint offset;
  uint count;
};

struct ClusterBounds {
  vec4 minView;  // view-space AABB of the froxel, padded
  vec4 maxView;
};

uint clusterCount() { return clusterGrid.counts.y; }

// 32-bit words of one tile's light mask (cluster_tiles.comp).
uint clusterMaskWords() { return (clusterGrid.counts.x + 31u) / 32u; }

// Whether a cluster's list was written; one that did not fit the index list is shaded by brute force.
// Written so that offset + count cannot wrap.
bool listFits(ClusterHeader h) {
  uint capacity = clusterGrid.counts.z;
  return h.count <= capacity && h.offset <= capacity - h.count;
}

// Demand can exceed 32 bits (many clusters x many lights): sums saturate instead of wrapping.
uint addSaturated(uint a, uint b) { return a > 0xFFFFFFFFu - b ? 0xFFFFFFFFu : a + b; }

uint depthSlice(float viewDepth) {
  float s = floor(log(viewDepth) * clusterGrid.slicing.z + clusterGrid.slicing.w);
  return uint(clamp(s, 0.0, float(clusterGrid.dims.z - 1u)));
}

uint clusterIndex(uvec2 pixel, float viewDepth) {
  uvec2 tile = min(pixel / clusterGrid.dims.w, clusterGrid.dims.xy - 1u);
  return (depthSlice(viewDepth) * clusterGrid.dims.y + tile.y) * clusterGrid.dims.x + tile.x;
}

uvec3 clusterCoords(uint index) {
  uint tx = index % clusterGrid.dims.x;
  uint rest = index / clusterGrid.dims.x;
  return uvec3(tx, rest % clusterGrid.dims.y, rest / clusterGrid.dims.y);
}

// Arvo 1990, "A Simple Method for Box-Sphere Intersection Testing": squared distance from the centre to the box.
bool sphereIntersectsAabb(vec3 center, float radius, vec3 lo, vec3 hi) {
  vec3 d = max(lo - center, 0.0) + max(center - hi, 0.0);
  return dot(d, d) <= radius * radius;
}
