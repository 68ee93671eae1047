#version 450 core
// Last pass of light assignment, after the scan: one invocation per slot writes its cluster's lights, found
// through the mask's summary words, lowest bit first, at the offset the scan computed, so every list comes out in
// ascending order: clustered shading sums lights in the same order as the brute-force path and the two agree bit
// for bit. It zeroes each mask and summary word it reads, so that the next window or frame starts from empty
// masks without clearing them whole (a list that does not fit is not written, but its mask is still cleared).
// Dispatched once per chunk of a window's lights, in ascending order, so that no invocation loops past llvmpipe's
// limit of 65535 iterations: a chunk of 131,072 lights has at most 128 summary words and 4,096 mask words, and its
// loop runs at most once per summary word, twice per mask word and once per four lights (41,088 times). The fill
// keeps its place in `cursors` between dispatches.
//
// With WORKGROUP_PER_SLOT a workgroup fills each slot (LightClusters::fillShape): its lanes take contiguous runs of
// the chunk's mask words, count their bits, and an exclusive prefix sum of the counts over the lanes gives each
// lane its place in the list, so the list comes out in the same ascending order as one invocation writes it, in
// about 1/64 of the time where lists are long (a GPU's shape; one invocation per slot suits llvmpipe's few wide
// threads). A lane's loops stay short: at most 64 mask words of a chunk, their summary words and their bits.
layout(local_size_x = 64) in;

#include "clusters.glsl"

// x: the chunk's first light counted from the window's (a multiple of 1024), y: its end; z: 1 for the frame's
// first chunk, w: 1 for its last.
layout(location = 0) uniform uvec4 fillChunk;

layout(std430, binding = CLUSTER_SSBO) readonly buffer Headers { ClusterHeader headers[]; };
layout(std430, binding = SLOT_CLUSTERS_SSBO) readonly buffer SlotClusters {
  uint activeCount;
  uint slotClusters[];
};
#define SLOT_MASKS_QUALIFIER
#include "slot_masks.glsl"
layout(std430, binding = LIGHT_INDEX_SSBO) writeonly buffer Indices { uint lightIndices[]; };
layout(std430, binding = CLUSTER_CURSOR_SSBO) buffer Cursors { uint cursors[]; };

uint gCursor;
bool gHigh;

// Reads a word of the slot's buffer (slot_masks.glsl) and leaves it zero.
uint takeSlotWord(uint i) {
  uint word;
  if (gHigh) {
    word = masksHigh[i];
    masksHigh[i] = 0u;
  } else {
    word = masksLow[i];
    masksLow[i] = 0u;
  }
  return word;
}

void writeLowestBit(inout uint bits, uint base) {
  if (bits == 0u) return;
  lightIndices[gCursor++] = base + uint(findLSB(bits));
  bits &= bits - 1u;
}

#if WORKGROUP_PER_SLOT
shared uint laneCounts[64];

// Bits [lo, hi) of a word (hi <= 32).
uint bitRange(uint lo, uint hi) { return hi <= lo ? 0u : (0xFFFFFFFFu >> (32u - (hi - lo))) << lo; }

// The slot's mask words in [begin, end) that its summary marks: pass 0 counts their bits, pass 1 writes their
// lights from gCursor and leaves them zero (the summary words are cleared after both passes).
uint walkMaskWords(uint summaryBase, uint maskBase, uint begin, uint end, bool write) {
  uint lights = 0u;
  for (uint w = begin; w < end;) {
    uint s = w / 32u, next = min(end, 32u * s + 32u);
    uint marked = (gHigh ? masksHigh[summaryBase + s] : masksLow[summaryBase + s]) & bitRange(w - 32u * s, next - 32u * s);
    while (marked != 0u) {
      uint m = 32u * s + uint(findLSB(marked));
      marked &= marked - 1u;
      if (write) {
        uint bits = takeSlotWord(maskBase + m), base = clusterGrid.window.x + 32u * m;
        while (bits != 0u) writeLowestBit(bits, base);
      } else {
        lights += uint(bitCount(gHigh ? masksHigh[maskBase + m] : masksLow[maskBase + m]));
      }
    }
    w = next;
  }
  return lights;
}

void fillSlot(uint slot) {
  uint lane = gl_LocalInvocationIndex;
  uint cluster = slotClusters[slot];
  ClusterHeader header = headers[cluster];
  bool writes = listFits(header);
  gHigh = slotIsHigh(slot);
  uint summaryBase = slotSummaryBase(slot), maskBase = slotMaskBase(slot);
  uint firstWord = fillChunk.x / 32u, endWord = min((fillChunk.y + 31u) / 32u, slotMaskWords());
  uint perLane = (max(endWord, firstWord) - firstWord + 63u) / 64u;
  uint begin = min(firstWord + lane * perLane, endWord), end = min(begin + perLane, endWord);
  uint start = fillChunk.z != 0u ? header.offset : cursors[cluster];
  laneCounts[lane] = writes ? walkMaskWords(summaryBase, maskBase, begin, end, false) : 0u;
  barrier();
  // Hillis-Steele inclusive scan of the lanes' counts.
  for (uint stride = 1u; stride < 64u; stride <<= 1u) {
    uint add = lane >= stride ? laneCounts[lane - stride] : 0u;
    barrier();
    laneCounts[lane] += add;
    barrier();
  }
  gCursor = start + (lane > 0u ? laneCounts[lane - 1u] : 0u);
  if (writes) {
    walkMaskWords(summaryBase, maskBase, begin, end, true);
  } else {
    // A list that does not fit is not written, but its mask is still cleared.
    for (uint m = begin; m < end; ++m) takeSlotWord(maskBase + m);
  }
  if (writes && fillChunk.w == 0u && lane == 63u) cursors[cluster] = gCursor;
  barrier();
  for (uint s = firstWord / 32u + lane; s < (endWord + 31u) / 32u; s += 64u) takeSlotWord(summaryBase + s);
}

void main() {
  // Slots in turn over at most 65,535 workgroups; every condition below is the workgroup's own, so the barriers
  // stay in uniform control flow.
  for (uint slot = gl_WorkGroupID.x; slot < min(activeCount, slotCapacity()); slot += gl_NumWorkGroups.x) {
    if (headers[slotClusters[slot]].count != 0u) fillSlot(slot);
    barrier();
  }
}
#else
void main() {
  uint slot = gl_GlobalInvocationID.x;
  if (slot >= min(activeCount, slotCapacity())) return;
  uint cluster = slotClusters[slot];
  ClusterHeader header = headers[cluster];
  // A cluster without lights has no bit set. One whose list does not fit the index buffer is shaded by brute
  // force: its mask is only cleared.
  if (header.count == 0u) return;
  bool writes = listFits(header);
  gHigh = slotIsHigh(slot);
  if (writes) gCursor = fillChunk.z != 0u ? header.offset : cursors[cluster];
  uint summaryBase = slotSummaryBase(slot), maskBase = slotMaskBase(slot);
  uint summaryEnd = min((fillChunk.y + 1023u) / 1024u, slotSummaryWords());
  // One loop, each iteration taking the next summary word where the last is spent, the next mask word where its
  // bits are, and writing up to four lights: a SIMD group loops as long as its busiest slot needs, rather than,
  // summary word by summary word, as long as the slot with the most lights under that word.
  uint s = fillChunk.x / 1024u, words = 0u, bits = 0u, wordBase = 0u, base = 0u;
  for (;;) {
    if (bits == 0u && words == 0u) {
      if (s >= summaryEnd) break;
      words = takeSlotWord(summaryBase + s);
      wordBase = 32u * s++;
    }
    if (bits == 0u && words != 0u) {
      uint w = wordBase + uint(findLSB(words));
      words &= words - 1u;
      bits = takeSlotWord(maskBase + w);
      base = clusterGrid.window.x + 32u * w;
      if (!writes) bits = 0u;
    }
    writeLowestBit(bits, base);
    writeLowestBit(bits, base);
    writeLowestBit(bits, base);
    writeLowestBit(bits, base);
  }
  if (writes && fillChunk.w == 0u) cursors[cluster] = gCursor;
}
#endif
