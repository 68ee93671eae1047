// The lighting pass's 8x8-pixel tiles sorted by surface_tiles.comp into those holding a surface and those showing
// only background (pbr::LightingPass): the deferred pass runs over the first, its BACKGROUND_TILES build over the
// second, each an indirect dispatch of a workgroup per listed tile. SURFACE_TILES_QUALIFIER: readonly where only read.
#ifndef SURFACE_TILES_QUALIFIER
#define SURFACE_TILES_QUALIFIER readonly
#endif
layout(std430, binding = SURFACE_TILES_SSBO) SURFACE_TILES_QUALIFIER buffer SurfaceTiles {
  uvec4 surfaceDispatch;     // xyz: the deferred pass's workgroups (below), w: tiles holding a surface
  uvec4 backgroundDispatch;  // xyz: the background build's workgroups, w: tiles of background only
  uvec4 tileGrid;            // x: tile columns, y: tiles in all
  uint tiles[];              // [0, surfaceDispatch.w) surface tiles, [tileGrid.y, + backgroundDispatch.w) the others
};

// A list's n workgroups are dispatched in rows of at most TILE_DISPATCH_ROW, n of them in one row up to it, so that
// no side passes the 65,535 a dispatch dimension is sure to take (GL_MAX_COMPUTE_WORK_GROUP_COUNT's least maximum;
// a 3840x2160 frame has 129,600 tiles); workgroup (x, y) takes entry y * TILE_DISPATCH_ROW + x, past n none.
const uint TILE_DISPATCH_ROW = 32768u;
