#version 450 core
// Last pass of light assignment (and of each window of it): zeroes the mask words the window set, found through
// the summary words, and the summaries, so that the next window's light pass starts from empty masks without
// clearing them whole (up to the masks' memory budget). One invocation per (slot, summary word).
layout(local_size_x = 64) in;

#include "clusters.glsl"

layout(std430, binding = SLOT_CLUSTERS_SSBO) readonly buffer SlotClusters {
  uint activeCount;
  uint slotClusters[];
};
layout(std430, binding = SLOT_MASKS_SSBO) buffer SlotMasks { uint slotMasks[]; };

void main() {
  uint summaryWords = slotSummaryWords();
  uint id = gl_GlobalInvocationID.x;
  if (id >= min(activeCount, slotCapacity()) * summaryWords) return;
  uint slot = id / summaryWords, s = id % summaryWords;
  uint summary = slotSummaryBase(slot) + s;
  uint words = slotMasks[summary];
  if (words == 0u) return;
  while (words != 0u) {
    slotMasks[slotMaskBase(slot) + s * 32u + uint(findLSB(words))] = 0u;
    words &= words - 1u;
  }
  slotMasks[summary] = 0u;
}
