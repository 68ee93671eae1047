#version 450 core
// Fine level of light assignment, compiled twice: ASSIGN_FILL 0 counts the lights touching each cluster,
// ASSIGN_FILL 1 writes their indices at the offsets the scan pass computed. A workgroup holds slices of one
// screen tile and visits only the lights of that tile's mask (cluster_tiles.comp), lowest bit first, so every
// list comes out in ascending order: clustered shading sums lights in the same order as the brute-force path
// and the two agree bit for bit. A light is listed when it passed its tile's side planes and its sphere touches
// the cluster's box.
layout(local_size_x = 8) in;

#include "clusters.glsl"

layout(std430, binding = CLUSTER_BOUNDS_SSBO) readonly buffer Bounds { ClusterBounds bounds[]; };
layout(std430, binding = CLUSTER_SSBO) buffer Headers { ClusterHeader headers[]; };
layout(std430, binding = CLUSTER_VIEW_LIGHTS_SSBO) readonly buffer ViewLights { vec4 viewLights[]; };
layout(std430, binding = CLUSTER_TILE_MASKS_SSBO) readonly buffer TileMasks { uint tileMasks[]; };
#if ASSIGN_FILL
layout(std430, binding = LIGHT_INDEX_SSBO) writeonly buffer Indices { uint lightIndices[]; };
#endif
#if ASSIGN_STATS && !ASSIGN_FILL
layout(std430, binding = LIGHT_VISIBLE_SSBO) buffer Visible { uint lightVisible[]; };
#endif

ClusterBounds gBox;
#if ASSIGN_FILL
uint gCursor;
#else
uint gCount;
#endif

void testLight(uint light) {
  vec4 sphere = viewLights[light];
  if (!sphereIntersectsAabb(sphere.xyz, sphere.w, gBox.minView.xyz, gBox.maxView.xyz)) return;
#if ASSIGN_FILL
  lightIndices[gCursor++] = light;
#else
  ++gCount;
#if ASSIGN_STATS
  lightVisible[light] = 1u;
#endif
#endif
}

void testLowestBit(inout uint bits, uint base) {
  if (bits == 0u) return;
  uint b = uint(findLSB(bits));
  bits &= bits - 1u;
  testLight(base + b);
}

void main() {
  uint tile = gl_WorkGroupID.x;
  uint slice = gl_WorkGroupID.y * gl_WorkGroupSize.x + gl_LocalInvocationIndex;
  if (slice >= clusterGrid.dims.z) return;
  uint cluster = slice * clusterGrid.dims.x * clusterGrid.dims.y + tile;
  gBox = bounds[cluster];
#if ASSIGN_FILL
  ClusterHeader header = headers[cluster];
  // A list that does not fit the index buffer is not written: lighting shades that cluster by brute force. Empty
  // clusters (most of them) have nothing to write.
  if (header.count == 0u || !listFits(header)) return;
  gCursor = header.offset;
#else
  gCount = 0u;
#endif
  uint words = clusterMaskWords();
  for (uint w = 0u; w < words; ++w) {
    uint bits = tileMasks[tile * words + w];
    // Four bits per iteration for llvmpipe's limit of 65535 loop iterations per invocation (see deferred.comp):
    // a tile reached by all of 65,536 lights takes 2,048 + 16,384 iterations.
    while (bits != 0u) {
      testLowestBit(bits, w * 32u);
      testLowestBit(bits, w * 32u);
      testLowestBit(bits, w * 32u);
      testLowestBit(bits, w * 32u);
    }
  }
#if !ASSIGN_FILL
  headers[cluster] = ClusterHeader(0u, gCount);
#endif
}
