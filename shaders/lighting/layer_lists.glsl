// Exact order-independent transparency's per-pixel lists (pbr::LayerListHeader, lighting/lighting_pass.hpp): every
// BLEND fragment a node, linked from its pixel's head; forward.frag appends, layer_resolve.comp sorts and composites.
// Heads and nodes share one storage buffer: one binding, sized and cleared together.

// Mirrors pbr::LayerListHeader, then a head per pixel of the frame (rows of frame width; the first node + 1, 0 for
// none), then the nodes, four words each: premultiplied colour rg and b with alpha as half floats, the fragment's
// reversed-Z depth as float bits, and the next node + 1.
layout(std430, binding = LAYER_NODE_SSBO) coherent buffer LayerLists {
  uint nodeCount;     // nodes asked for, also past the capacity
  uint nodeCapacity;
  uint droppedNodes;  // fragments without a node (over capacity) or left out of a pixel's sort (over MAX_LAYERS)
  uint heads;         // pixels: the nodes start at word `heads` of `words`, the heads at word 0
  uint words[];
};

uvec4 layerNode(uint node) {
  uint at = heads + 4u * node;
  return uvec4(words[at], words[at + 1u], words[at + 2u], words[at + 3u]);
}
