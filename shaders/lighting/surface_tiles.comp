#version 450 core
// Sorts the lighting pass's 8x8-pixel tiles into those where a pixel holds a surface (depth > 0, as readSurface
// tests it) and those of background only, appending each to its list (surface_tiles.glsl). On llvmpipe a workgroup
// runs its whole shader under lane masks even where every pixel returns at once (an empty 1280x720 frame's deferred
// pass took 81-87 ms), so a tile of sky costs as much as a lit one unless it is never dispatched. An invocation per
// tile, looking until it finds a surface: a frame covered by surfaces is sorted at one read a tile, and no barrier
// (which llvmpipe pays for by switching between the workgroup's invocations) is needed.
layout(local_size_x = 64) in;

#include "../common/frame.glsl"
#define SURFACE_TILES_QUALIFIER
#include "surface_tiles.glsl"

layout(binding = SURFACE_DEPTH_UNIT) uniform sampler2D gDepth;

void main() {
  uint tile = gl_GlobalInvocationID.x;
  if (tile >= tileGrid.y) return;
  ivec2 origin = ivec2(tile % tileGrid.x, tile / tileGrid.x) * 8;
  bool surface = false;
  for (int i = 0; i < 64 && !surface; ++i) {
    ivec2 p = origin + ivec2(i % 8, i / 8);
    surface = all(lessThan(p, ivec2(frame.viewport.xy))) && texelFetch(gDepth, p, 0).r > 0.0;
  }
  // The entry's place, then the dispatch grown to take it (surface_tiles.glsl): entries of the first row widen it, the
  // first entry of each row adds the row.
  uint entry;
  if (surface) {
    entry = atomicAdd(surfaceDispatch.w, 1u);
    tiles[entry] = tile;
    if (entry < TILE_DISPATCH_ROW) atomicAdd(surfaceDispatch.x, 1u);
    if (entry % TILE_DISPATCH_ROW == 0u) atomicAdd(surfaceDispatch.y, 1u);
  } else {
    entry = atomicAdd(backgroundDispatch.w, 1u);
    tiles[tileGrid.y + entry] = tile;
    if (entry < TILE_DISPATCH_ROW) atomicAdd(backgroundDispatch.x, 1u);
    if (entry % TILE_DISPATCH_ROW == 0u) atomicAdd(backgroundDispatch.y, 1u);
  }
}
