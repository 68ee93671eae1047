#version 450 core
// Coarse level of two-level light assignment: which lights reach each screen tile's frustum column, as one bit
// per light (word w, bit b: light 32 w + b), so the cluster passes visit a tile's lights in ascending order
// without a sort. One invocation per (tile, 32-light word). A light passes when its sphere is on the inner side
// of, or within its radius of, each of the tile's four side planes (Olsson et al. 2012, "Clustered Deferred and
// Forward Shading"); the cluster passes then test only those lights against their froxel boxes.
layout(local_size_x = 64) in;

#include "../common/frame.glsl"
#include "clusters.glsl"

layout(std430, binding = CLUSTER_VIEW_LIGHTS_SSBO) readonly buffer ViewLights { vec4 viewLights[]; };
layout(std430, binding = CLUSTER_TILE_MASKS_SSBO) writeonly buffer TileMasks { uint tileMasks[]; };

// Unit inward normals of the column's left, right, bottom and top planes (all through the eye), and how far
// outside them a pixel of the tile may still land: 1e-4 of the column's farthest corner, far above the rounding
// of a position reconstructed from depth.
struct TilePlanes {
  vec3 normals[4];
  float pad;
};

TilePlanes tilePlanes(uvec2 tile) {
  vec2 pixelLo = vec2(tile * clusterGrid.dims.w);
  vec2 pixelHi = min(vec2((tile + 1u) * clusterGrid.dims.w), frame.viewport.xy);
  vec2 lo = (pixelLo * frame.viewport.zw * 2.0 - 1.0) / frame.projParams.xy;
  vec2 hi = (pixelHi * frame.viewport.zw * 2.0 - 1.0) / frame.projParams.xy;
  TilePlanes t;
  t.normals[0] = normalize(vec3(1.0, 0.0, lo.x));
  t.normals[1] = normalize(vec3(-1.0, 0.0, -hi.x));
  t.normals[2] = normalize(vec3(0.0, 1.0, lo.y));
  t.normals[3] = normalize(vec3(0.0, -1.0, -hi.y));
  vec2 corner = max(abs(lo), abs(hi));
  t.pad = 1e-4 * clusterGrid.slicing.y * length(vec3(corner, 1.0)) + 1e-6;
  return t;
}

bool sphereInTileColumn(TilePlanes t, vec4 sphere) {
  float reach = -(sphere.w + t.pad);
  return dot(t.normals[0], sphere.xyz) >= reach && dot(t.normals[1], sphere.xyz) >= reach &&
         dot(t.normals[2], sphere.xyz) >= reach && dot(t.normals[3], sphere.xyz) >= reach;
}

void main() {
  uint words = clusterMaskWords();
  uint tiles = clusterGrid.dims.x * clusterGrid.dims.y;
  uint id = gl_GlobalInvocationID.x;
  if (id >= tiles * words) return;
  uint tile = id / words, word = id % words;
  TilePlanes planes = tilePlanes(uvec2(tile % clusterGrid.dims.x, tile / clusterGrid.dims.x));
  uint base = word * 32u;
  uint n = min(32u, clusterGrid.counts.x - base);
  uint mask = 0u;
  for (uint b = 0u; b < n; ++b) {
    if (sphereInTileColumn(planes, viewLights[base + b])) mask |= 1u << b;
  }
  tileMasks[id] = mask;
}
