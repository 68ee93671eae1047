// The pixel an invocation of a per-pixel dispatch (one workgroup per screen tile) works on, for passes whose cost
// differs between tiles (sky against surface): the lighting pass. llvmpipe hands each of its threads one contiguous run of a
// dispatch's workgroups, so in row order a thread whose rows show sky finishes early while another shades the model:
// the workgroups are dealt to tiles in TILE_BANDS interleaved bands instead (workgroup i takes a tile of band
// i mod TILE_BANDS, the bands each a contiguous run of tiles), so that every run of workgroups holds tiles from all
// over the frame. A bijection of the dispatch's workgroups: every tile is visited once (docs/performance.md).
const uint TILE_BANDS = 16u;

ivec2 dealtPixel() {
  uint columns = gl_NumWorkGroups.x, n = columns * gl_NumWorkGroups.y;
  uint i = gl_WorkGroupID.y * columns + gl_WorkGroupID.x;
  uint band = i % TILE_BANDS, perBand = n / TILE_BANDS, longer = n % TILE_BANDS;
  uint tile = band * perBand + min(band, longer) + i / TILE_BANDS;
  return ivec2(uvec2(tile % columns, tile / columns) * gl_WorkGroupSize.xy + gl_LocalInvocationID.xy);
}
