#version 450 core
// Exclusive prefix sum of the light counts of the clusters with a slot, in slot order, into list offsets, in one
// workgroup: each invocation scans a contiguous chunk of slots serially, the chunk totals are scanned in shared
// memory (Hillis-Steele), then each chunk adds its base. Visiting the slots rather than every cluster (192 slices
// of every tile) keeps the serial chunks short. Also totals the demand for the index list and the cluster
// statistics. Clusters without surface or slot keep their CLUSTER_INACTIVE offset and count nothing; those
// without slot count as overflowed.
layout(local_size_x = 1024) in;

#include "clusters.glsl"

layout(std430, binding = CLUSTER_SSBO) buffer Headers { ClusterHeader headers[]; };

// Mirrors pbr::ClusterStatus (lighting/cluster_block.hpp).
layout(std430, binding = CLUSTER_STATUS_SSBO) writeonly buffer Status {
  uint demand;         // index-list entries all clusters need (saturates at 2^32 - 1)
  uint nonEmpty;       // clusters with at least one light
  uint maxPerCluster;
  uint visibleLights;  // lights touching at least one cluster (stats mode only)
  uint overflowed;     // clusters whose list does not fit the index list
  uint capacity;       // the index list's capacity this frame
  uint activeClusters; // clusters holding a surface
  uint unslotted;      // of those, clusters past the masks' slot capacity
} status;

layout(std430, binding = SLOT_CLUSTERS_SSBO) readonly buffer SlotClusters {
  uint activeCount;
  uint slotClusters[];
};

#if ASSIGN_STATS
layout(std430, binding = LIGHT_VISIBLE_SSBO) buffer Visible { uint lightVisible[]; };
#endif

shared uint partial[1024];
shared uint nonEmptyCount;
shared uint maxCount;
shared uint visibleCount;
shared uint overflowCount;

void main() {
  uint t = gl_LocalInvocationIndex;
  uint n = min(activeCount, slotCapacity());
  uint chunk = (n + 1023u) / 1024u;
  uint begin = min(t * chunk, n), end = min(begin + chunk, n);
  if (t == 0u) {
    nonEmptyCount = 0u;
    maxCount = 0u;
    visibleCount = 0u;
    overflowCount = 0u;
  }
  uint sum = 0u, localNonEmpty = 0u, localMax = 0u;
  for (uint i = begin; i < end; ++i) {
    uint c = headers[slotClusters[i]].count;
    sum = addSaturated(sum, c);
    localNonEmpty += c > 0u ? 1u : 0u;
    localMax = max(localMax, c);
  }
  partial[t] = sum;
  barrier();
  atomicAdd(nonEmptyCount, localNonEmpty);
  atomicMax(maxCount, localMax);
  for (uint stride = 1u; stride < 1024u; stride <<= 1u) {
    uint add = t >= stride ? partial[t - stride] : 0u;
    barrier();
    partial[t] = addSaturated(partial[t], add);
    barrier();
  }
  // Recomputed serially rather than as partial - sum, which is wrong once the total saturates.
  uint offset = t > 0u ? partial[t - 1u] : 0u;
  uint localOverflow = 0u;
  for (uint i = begin; i < end; ++i) {
    uint cluster = slotClusters[i];
    ClusterHeader h = ClusterHeader(offset, headers[cluster].count);
    headers[cluster].offset = offset;
    localOverflow += listFits(h) ? 0u : 1u;
    offset = addSaturated(offset, h.count);
  }
  atomicAdd(overflowCount, localOverflow);
#if ASSIGN_STATS
  uint lightCount = clusterGrid.counts.x;
  uint lightChunk = (lightCount + 1023u) / 1024u;
  uint visible = 0u;
  for (uint i = min(t * lightChunk, lightCount); i < min((t + 1u) * lightChunk, lightCount); ++i) {
    visible += lightVisible[i];
    lightVisible[i] = 0u;
  }
  atomicAdd(visibleCount, visible);
#endif
  barrier();
  if (t == 1023u) {
    uint unslotted = activeCount - min(activeCount, slotCapacity());
    status.demand = partial[1023];
    status.nonEmpty = nonEmptyCount;
    status.maxPerCluster = maxCount;
    status.visibleLights = visibleCount;
    status.overflowed = overflowCount + unslotted;
    status.capacity = clusterGrid.counts.z;
    status.activeClusters = activeCount;
    status.unslotted = unslotted;
  }
}
