// Which of a dispatch's n workgroups takes list entry dealtIndex(i, n), for passes whose cost differs between
// tiles (the lighting pass: a tile of the model against one mostly sky). llvmpipe hands each of its threads one
// contiguous run of a dispatch's workgroups, so with the tiles in screen order a thread whose run holds the sky
// finishes early while another shades the model: the entries are dealt in TILE_BANDS interleaved bands instead
// (workgroup i takes an entry of band i mod TILE_BANDS, the bands each a contiguous run), so that every run of
// workgroups holds tiles from all over the frame. A bijection of [0, n): every entry is visited once
// (docs/performance.md).
const uint TILE_BANDS = 16u;

uint dealtIndex(uint i, uint n) {
  uint band = i % TILE_BANDS, perBand = n / TILE_BANDS, longer = n % TILE_BANDS;
  return band * perBand + min(band, longer) + i / TILE_BANDS;
}
