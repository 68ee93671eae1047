#version 450 core
// Light assignment, compiled twice: ASSIGN_FILL 0 counts the lights touching each cluster, ASSIGN_FILL 1 writes
// their indices at the offsets the scan pass computed. Each workgroup walks the frame's lights in ascending
// order, a batch at a time, transforming each light to view space once into shared memory; each invocation
// tests its own cluster. Ascending order keeps every list sorted, so clustered shading sums lights in the same
// order as the brute-force path and the two agree bit for bit.
layout(local_size_x = 64) in;

#include "../common/frame.glsl"
#include "clusters.glsl"
#include "lights.glsl"

layout(std430, binding = CLUSTER_BOUNDS_SSBO) readonly buffer Bounds { ClusterBounds bounds[]; };
layout(std430, binding = CLUSTER_SSBO) buffer Headers { ClusterHeader headers[]; };
#if ASSIGN_FILL
layout(std430, binding = LIGHT_INDEX_SSBO) writeonly buffer Indices { uint lightIndices[]; };
#endif
#if ASSIGN_STATS && !ASSIGN_FILL
layout(std430, binding = LIGHT_VISIBLE_SSBO) buffer Visible { uint lightVisible[]; };
#endif

shared vec4 batch[64];  // view-space centre, radius

ClusterBounds gBox;
#if ASSIGN_FILL
uint gCursor;
#else
uint gCount;
#endif

void testLight(uint base, uint j) {
  vec4 sphere = batch[j];
  if (!sphereIntersectsAabb(sphere.xyz, sphere.w, gBox.minView.xyz, gBox.maxView.xyz)) return;
#if ASSIGN_FILL
  lightIndices[gCursor++] = base + j;
#else
  ++gCount;
#if ASSIGN_STATS
  lightVisible[base + j] = 1u;
#endif
#endif
}

void main() {
  uint cluster = gl_GlobalInvocationID.x;
  bool inRange = cluster < clusterCount();
  gBox = bounds[min(cluster, clusterCount() - 1u)];
#if ASSIGN_FILL
  ClusterHeader header = headers[min(cluster, clusterCount() - 1u)];
  // A list that does not fit the index buffer is not written: lighting shades that cluster by brute force.
  inRange = inRange && listFits(header);
  gCursor = header.offset;
#else
  gCount = 0u;
#endif
  uint total = clusterGrid.counts.x;
  for (uint base = 0u; base < total; base += 64u) {
    uint li = base + gl_LocalInvocationIndex;
    if (li < total) {
      vec4 pr = lights[li].positionRadius;
      batch[gl_LocalInvocationIndex] = vec4((frame.view * vec4(pr.xyz, 1.0)).xyz, pr.w);
    }
    barrier();
    uint n = min(64u, total - base);
    if (inRange) {
      // Unrolled by 8 for llvmpipe's limit of 65535 loop iterations per invocation (see deferred.comp).
      uint j = 0u;
      for (; j + 8u <= n; j += 8u) {
        testLight(base, j);
        testLight(base, j + 1u);
        testLight(base, j + 2u);
        testLight(base, j + 3u);
        testLight(base, j + 4u);
        testLight(base, j + 5u);
        testLight(base, j + 6u);
        testLight(base, j + 7u);
      }
      for (; j < n; ++j) testLight(base, j);
    }
    barrier();
  }
#if !ASSIGN_FILL
  if (inRange) headers[cluster] = ClusterHeader(0u, gCount);
#endif
}
