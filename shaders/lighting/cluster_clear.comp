#version 450 core
// Last pass of light assignment: zeroes the mask words the frame set, found through the summary words, and the
// summaries, so that the next frame's light pass starts from empty masks without clearing them whole (31 MiB at
// a million lights and 1280x720). One invocation per (tile, summary word).
layout(local_size_x = 64) in;

#include "clusters.glsl"

layout(std430, binding = CLUSTER_TILE_MASKS_SSBO) writeonly buffer TileMasks { uint tileMasks[]; };
layout(std430, binding = CLUSTER_TILE_WORDS_SSBO) buffer TileWords { uint tileWords[]; };

void main() {
  uint summaryWords = clusterSummaryWords();
  uint id = gl_GlobalInvocationID.x;
  if (id >= tileCount() * summaryWords) return;
  uint tile = id / summaryWords, s = id % summaryWords;
  uint words = tileWords[id];
  if (words == 0u) return;
  while (words != 0u) {
    tileMasks[tile * clusterMaskWords() + s * 32u + uint(findLSB(words))] = 0u;
    words &= words - 1u;
  }
  tileWords[id] = 0u;
}
