// The lighting pass's 8x8-pixel tiles sorted by surface_tiles.comp into those holding a surface and those showing
// only background (pbr::LightingPass): the deferred pass runs over the first, its BACKGROUND_TILES build over the
// second, each an indirect dispatch of the count here. SURFACE_TILES_QUALIFIER: readonly where only read.
#ifndef SURFACE_TILES_QUALIFIER
#define SURFACE_TILES_QUALIFIER readonly
#endif
layout(std430, binding = SURFACE_TILES_SSBO) SURFACE_TILES_QUALIFIER buffer SurfaceTiles {
  uvec4 surfaceDispatch;     // x: tiles holding a surface, the deferred pass's workgroups; y = z = 1
  uvec4 backgroundDispatch;  // x: tiles of background only; y = z = 1
  uvec4 tileGrid;            // x: tile columns, y: tiles in all
  uint tiles[];              // [0, surfaceDispatch.x) surface tiles, [tileGrid.y, + backgroundDispatch.x) the others
};
