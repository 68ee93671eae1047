#version 450 core
// Fine level of light assignment, compiled twice: ASSIGN_FILL 0 counts the lights touching each cluster,
// ASSIGN_FILL 1 writes their indices at the offsets the scan pass computed. A workgroup holds slices of one
// screen tile and visits only the lights of that tile's mask (cluster_lights.comp), found through its summary
// words, lowest first, so every list comes out in ascending order: clustered shading sums lights in the same
// order as the brute-force path and the two agree bit for bit. A light is listed when its tile took it and its
// sphere touches the box of the surfaces the cluster holds (cluster_occupancy.comp), and a spot light's cone the
// box's bounding sphere; clusters without surface get no list.
//
// Dispatched once per chunk of lights (assignChunk), in ascending order, so that no invocation loops past
// llvmpipe's limit of 65535 iterations: a chunk of 131,072 lights takes at most 128 summary words, 4,096 mask
// words and 32,768 four-bit steps. Counts add up over the chunks; the fill keeps its place in `cursors`.
layout(local_size_x = 8) in;

#include "clusters.glsl"

// x: the chunk's first light (a multiple of 1024), y: its end, z: 1 for the first chunk, w: 1 for the last.
layout(location = 0) uniform uvec4 assignChunk;

layout(std430, binding = CLUSTER_SSBO) buffer Headers { ClusterHeader headers[]; };
layout(std430, binding = CLUSTER_VIEW_LIGHTS_SSBO) readonly buffer ViewLights { vec4 viewLights[]; };
#if SPOT_LIGHTS
layout(std430, binding = CLUSTER_VIEW_CONES_SSBO) readonly buffer ViewCones { vec4 viewCones[]; };
#endif
layout(std430, binding = CLUSTER_OCCUPANCY_SSBO) readonly buffer Occupancy { uint occupancy[]; };
layout(std430, binding = CLUSTER_TILE_MASKS_SSBO) readonly buffer TileMasks { uint tileMasks[]; };
layout(std430, binding = CLUSTER_TILE_WORDS_SSBO) readonly buffer TileWords { uint tileWords[]; };
#if ASSIGN_FILL
layout(std430, binding = LIGHT_INDEX_SSBO) writeonly buffer Indices { uint lightIndices[]; };
layout(std430, binding = CLUSTER_CURSOR_SSBO) buffer Cursors { uint cursors[]; };
#endif
#if ASSIGN_STATS && !ASSIGN_FILL
layout(std430, binding = LIGHT_VISIBLE_SSBO) buffer Visible { uint lightVisible[]; };
#endif

vec3 gBoxLo, gBoxHi;
#if ASSIGN_FILL
uint gCursor;
#else
uint gCount;
#endif

void testLight(uint light) {
  vec4 sphere = viewLights[light];
  if (!sphereIntersectsAabb(sphere.xyz, sphere.w, gBoxLo, gBoxHi)) return;
#if SPOT_LIGHTS
  if (!coneIntersectsAabb(viewCones[2u * light], viewCones[2u * light + 1u], gBoxLo, gBoxHi)) return;
#endif
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
  uint cluster = slice * tileCount() + tile;
  bool firstChunk = assignChunk.z != 0u;
  uint base = clusterBoxBase(cluster);
  if (!occupiedBox(uvec3(occupancy[base], occupancy[base + 1u], occupancy[base + 2u]),
                   uvec3(occupancy[base + 3u], occupancy[base + 4u], occupancy[base + 5u]), gBoxLo, gBoxHi)) {
#if !ASSIGN_FILL
    if (firstChunk) headers[cluster] = ClusterHeader(CLUSTER_INACTIVE, 0u);
#endif
    return;
  }
#if ASSIGN_FILL
  ClusterHeader header = headers[cluster];
  // A list that does not fit the index buffer is not written: lighting shades that cluster by brute force. Empty
  // clusters have nothing to write.
  if (header.count == 0u || !listFits(header)) return;
  gCursor = firstChunk ? header.offset : cursors[cluster];
#else
  gCount = 0u;
#endif
  uint summaryWords = clusterSummaryWords(), maskWords = clusterMaskWords();
  uint summaryEnd = min((assignChunk.y + 1023u) / 1024u, summaryWords);
  for (uint s = assignChunk.x / 1024u; s < summaryEnd; ++s) {
    uint words = tileWords[tile * summaryWords + s];
    while (words != 0u) {
      uint w = s * 32u + uint(findLSB(words));
      words &= words - 1u;
      uint bits = tileMasks[tile * maskWords + w];
      while (bits != 0u) {
        testLowestBit(bits, w * 32u);
        testLowestBit(bits, w * 32u);
        testLowestBit(bits, w * 32u);
        testLowestBit(bits, w * 32u);
      }
    }
  }
#if ASSIGN_FILL
  if (assignChunk.w == 0u) cursors[cluster] = gCursor;
#else
  headers[cluster] = ClusterHeader(0u, firstChunk ? gCount : addSaturated(headers[cluster].count, gCount));
#endif
}
