#version 450 core
// Exact order-independent transparency's resolve: each pixel's BLEND fragments (layer_lists.glsl) in depth order,
// nearest first, composited front to back over what lies behind them, Porter-Duff "over" of premultiplied colour
// (Porter & Duff 1984): C += T c, T *= 1 - a, then C + T behind. The order is found by selection, a walk of the
// list for each next node: no local array, whose dynamic indexing llvmpipe (Mesa 22.3) miscompiles here. At most
// MAX_LAYERS fragments of a pixel are composited, the nearest of the first kMaxWalk in its list; the others are
// counted as dropped. The bounds keep an invocation's loop iterations (MAX_LAYERS x kMaxWalk + kMaxCount) under
// the 65,535 after which llvmpipe ends it.
layout(local_size_x = 8, local_size_y = 8) in;

#include "../common/math.glsl"
#include "layer_lists.glsl"

layout(HDR_IMAGE_FORMAT, binding = RADIANCE_IMAGE) uniform image2D radiance;

const uint kMaxWalk = 512u;     // nodes of a pixel ordered
const uint kMaxCount = 16384u;  // nodes past them counted as dropped

// A node's place in the order: nearer first (larger reversed-Z depth); at the same depth a later chunk of a layer's
// lights (alpha 0) before the layer's own node, so that it is covered as that layer is; then by index.
struct Key {
  float depth;
  bool chunk;
  uint node;
};

Key keyOf(uint node, uvec4 n) { return Key(uintBitsToFloat(n.z), unpackHalf2x16(n.y).y == 0.0, node); }

bool before(Key a, Key b) {
  if (a.depth != b.depth) return a.depth > b.depth;
  if (a.chunk != b.chunk) return a.chunk;
  return a.node < b.node;
}

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(radiance)))) return;
  uint head = words[uint(p.y) * uint(imageSize(radiance).x) + uint(p.x)];
  if (head == 0u) return;
  vec3 color = vec3(0.0);
  float covered = 1.0;  // T: the share of what lies behind that still shows
  Key last = Key(1.0 / 0.0, true, 0u);  // before every node
  uint composited = 0u;
  for (; composited < MAX_LAYERS; ++composited) {
    bool found = false;
    Key best;
    uvec4 bestNode;
    uint walked = 0u;
    for (uint node = head; node != 0u && walked < kMaxWalk; ++walked) {
      uvec4 n = layerNode(node - 1u);
      Key k = keyOf(node, n);
      if (before(last, k) && (!found || before(k, best))) {
        found = true;
        best = k;
        bestNode = n;
      }
      node = n.w;
    }
    if (!found) break;
    vec2 rg = unpackHalf2x16(bestNode.x), ba = unpackHalf2x16(bestNode.y);
    color += covered * vec3(rg, ba.x);
    covered *= 1.0 - ba.y;
    last = best;
  }
  // What was left out: the nodes past the first kMaxWalk, and of those, what MAX_LAYERS did not take.
  uint listed = 0u;
  for (uint node = head; node != 0u && listed < kMaxWalk + kMaxCount; ++listed) node = layerNode(node - 1u).w;
  if (listed > composited) atomicAdd(droppedNodes, listed - composited);
  color += covered * imageLoad(radiance, p).rgb;
  // NaN compares false everywhere: keep only values known to be finite and non-negative.
  color = mix(vec3(0.0), color, greaterThanEqual(color, vec3(0.0)));
  imageStore(radiance, p, vec4(min(color, vec3(HDR_MAX)), 1.0));
}
